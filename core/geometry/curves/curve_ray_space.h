// Pieces shared by the exact and the distance-aware ray/curve intersectors: the ray-space frame
// (the ray becomes the +z axis), the bound test and the refinement depth of Nakamaru & Ohno.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math/ray.h"
#include "core/math/vec.h"

namespace darc {

// Cap on the subdivision depth (2^10 leaves): pbrt's clamp; deeper only costs time once the
// leaves are flatter than a float can tell.
constexpr int kMaxRefinementDepth = 10;
// Leaves are refined until they deviate from their chord by less than width / 20 (Nakamaru &
// Ohno's epsilon, as in pbrt).
constexpr float kFlatnessWidthFraction = 20.0f;
// The ray-space frame takes its "up" from d x chord unless the sine of their angle is below this;
// then any perpendicular frame is as good (the curve is seen end-on).
constexpr double kParallelSine = 1e-9;
// A leaf whose projected chord is shorter than this fraction of its width is seen end-on: it is
// tested as a point (its nearer end) instead of projecting onto a chord with no direction.
constexpr float kPointChordFraction = 1e-3f;

// An orthonormal right-handed frame whose z axis is the unit ray direction.
struct RayFrame {
  Vec3d x, y, z;
  Vec3f to_ray_space(const Vec3d& p) const { return Vec3f(Vec3d{dot(p, x), dot(p, y), dot(p, z)}); }
};

// x is chosen in the plane of the ray and the chord so that the projected curve lies along x
// and its bound is thin in y.
inline RayFrame make_ray_frame(const Vec3d& dir, const Vec3d& chord) {
  RayFrame f;
  f.z = dir;
  Vec3d up = cross(dir, chord);
  double chord_length = length(chord);
  if (chord_length > 0 && length(up) > kParallelSine * chord_length) {
    f.x = normalize(cross(up, dir));
  } else {
    Vec3d unused;
    orthonormal_basis(dir, f.x, unused);
  }
  f.y = cross(f.z, f.x);
  return f;
}

// Does the control-point bound grown by `margin` touch the ray (the z axis) within [z_lo, z_hi]?
inline bool bound_overlaps_ray(const Vec3f cp[4], float margin, float z_lo, float z_hi) {
  Vec3f lo = min(min(cp[0], cp[1]), min(cp[2], cp[3]));
  Vec3f hi = max(max(cp[0], cp[1]), max(cp[2], cp[3]));
  return lo.x - margin <= 0.0f && hi.x + margin >= 0.0f && lo.y - margin <= 0.0f && hi.y + margin >= 0.0f &&
         lo.z - margin <= z_hi && hi.z + margin >= z_lo;
}

// Subdivisions needed for leaves flat to within width/20. L0 bounds the second differences of
// the control points; Nakamaru's erratum includes z, because the leaf's u comes from a 2D
// projection and control points spaced unevenly along the ray otherwise give a wrong u (and t).
inline int refinement_depth(const Vec3f cp[4], float max_width) {
  float l0 = 0.0f;
  for (int i = 0; i < 2; ++i) l0 = std::max(l0, max_component(abs(cp[i] - cp[i + 1] * 2.0f + cp[i + 2])));
  if (!(l0 > 0.0f)) return 0;  // a straight segment is one leaf (and log(0) is undefined)
  float eps = max_width / kFlatnessWidthFraction;
  // Degree 3: N(N-1) = 6 in the flatness bound (pbrt-v3 #76).
  float ratio = std::sqrt(2.0f) * 6.0f * l0 / (8.0f * eps);
  if (!std::isfinite(ratio)) return kMaxRefinementDepth;
  int depth = static_cast<int>(std::ceil(0.5f * std::log2(std::max(ratio, 1.0f))));
  return std::clamp(depth, 0, kMaxRefinementDepth);
}

// A cheap rejection before the ray frame is built: the segment lies within the sphere around
// the mean of its control points through the farthest one; the ray, widened to a cone of radius
// reach0 + reach1 * t (zero for the exact test), must pass within that radius + margin, inside
// its t interval. In double, so that coordinates far from the origin lose nothing.
inline bool bounding_sphere_may_hit(const Vec3f cp[4], float margin, const Ray& ray, float reach0 = 0.0f,
                                    float reach1 = 0.0f) {
  Vec3d c = (Vec3d(cp[0]) + Vec3d(cp[1]) + Vec3d(cp[2]) + Vec3d(cp[3])) * 0.25;
  double r2 = 0;
  for (int i = 0; i < 4; ++i) r2 = std::max(r2, length_squared(Vec3d(cp[i]) - c));
  double r = std::sqrt(r2) + margin;
  Vec3d d(ray.d), oc = c - Vec3d(ray.o);
  double dd = dot(d, d);
  double tc = dot(oc, d) / dd, dt = r / std::sqrt(dd);
  if (tc + dt < ray.tmin || tc - dt > ray.tmax) return false;
  double reach = reach0 + reach1 * std::max(0.0, tc + dt);
  double limit = r + reach;
  return length_squared(oc - d * tc) <= limit * limit * (1 + 1e-6) + 1e-12;
}

}  // namespace darc
