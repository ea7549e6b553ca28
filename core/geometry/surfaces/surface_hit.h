// The result of intersecting a ray with a surface primitive (sphere, polygon).
#pragma once

#include "core/math/vec.h"

namespace darc {

struct SurfaceHit {
  float t = 0;  // ray parameter of the hit: p = ray.o + t * ray.d
  Vec3f p;      // hit point, world space
  // Geometric normal, world space, unit length, as the surface defines it (outward for a
  // sphere, the vertex-order normal for a polygon). Never flipped toward the ray: the caller
  // applies RI Orientation / ReverseOrientation and two-sided shading.
  Vec3f ng;
  // Surface parameters in [0, 1] where the primitive defines them (sphere: u along theta,
  // v along latitude from zmin to zmax); 0 for polygons, which have no RI parametrization.
  float u = 0, v = 0;
};

}  // namespace darc
