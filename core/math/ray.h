// A ray in world space: points o + t*d for t in [tmin, tmax]. d need not be unit length
// (camera rays keep |d| = 1 so that t is a distance).
#pragma once

#include "core/math/vec.h"

#include <limits>

namespace darc {

struct Ray {
  Vec3f o;
  Vec3f d;
  float tmin = 0.0f;
  float tmax = std::numeric_limits<float>::infinity();
  // Motion blur: the shutter time (0 at open, 1 at close) at which the ray sees moving geometry.
  float time = 0.0f;
  // The distance hider's rays stand for a stretch of the shutter, [sweep_from, sweep_to] (its time
  // strata): a moving strand gives the coverage it has averaged over it (its shape at `time`, the
  // stretch's middle, for depth and shading).
  bool sweeps_shutter = false;
  float sweep_from = 0.0f, sweep_to = 1.0f;

  Vec3f at(float t) const { return o + d * t; }
};

}  // namespace darc
