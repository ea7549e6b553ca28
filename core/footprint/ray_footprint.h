// A ray's footprint from its ray differentials (Igehy 1999): at distance t the sample spacing
// is spanned by axis_x(t) = dox + t*ddx and axis_y(t) = doy + t*ddy (world-space vectors that
// are, to first order, perpendicular to the ray). Camera rays of a perspective camera have
// dox = doy = 0; orthographic ones ddx = ddy = 0.
#pragma once

#include "core/math/vec.h"

#include <cmath>

namespace darc {

struct RayFootprint {
  Vec3f dox, doy, ddx, ddy;
  // Floor on the footprint size, so that r -> 0 (a pinhole at its apex, a ray without
  // differentials) never divides by zero: below it coverage becomes a plain hit test.
  float min_radius = 0;

  Vec3f axis_x(float t) const { return dox + ddx * t; }
  Vec3f axis_y(float t) const { return doy + ddy * t; }
  bool has_differentials() const {
    return length_squared(dox) + length_squared(doy) + length_squared(ddx) + length_squared(ddy) > 0;
  }
  // Upper bound on how far from the ray a strand can be and still cover part of the footprint:
  // half the sum of the axes (reaches the square's corners), linear in t.
  float reach(float t) const {
    return 0.5f * (length(dox) + length(doy)) + 0.5f * (length(ddx) + length(ddy)) * std::abs(t);
  }
};

}  // namespace darc
