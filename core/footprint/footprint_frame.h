// A ray's footprint prepared for analytic coverage: where its sub-rays start and go, in double
// precision, and the 8x8 mask points' sub-rays computed once, so that every primitive the ray
// meets evaluates its edges at bitwise the same sub-rays (the condition for neighbouring
// pieces to own each mask point exactly once, footprint-everything.md §2.3).
//
// Footprint coordinates (u, v) in Q = [-1/2, 1/2]^2 are the sub-ray parameters (RayFootprint):
// coverage is the fraction of Q whose sub-rays hit, the box filter over the footprint.
#pragma once

#include "core/footprint/coverage_mask.h"
#include "core/footprint/ray_footprint.h"
#include "core/math/ray.h"
#include "core/math/vec.h"

#include <array>
#include <span>

namespace darc {

// The (u, v) of mask point b (column b % kMaskSide, row b / kMaskSide).
inline float mask_point_u(int b) { return (float(b % kMaskSide) + 0.5f) / float(kMaskSide) - 0.5f; }
inline float mask_point_v(int b) { return (float(b / kMaskSide) + 0.5f) / float(kMaskSide) - 0.5f; }

struct FootprintFrame {
  // Pencil or Parallel; a General footprint (reflected and refracted rays) has no frame, and
  // its surfaces keep the sub-ray tests.
  FootprintForm form = FootprintForm::General;
  Vec3d o, d, dox, doy, ddx, ddy;
  // Pencil: every sub-ray passes through the apex, at parameter apex_t. The ray's interval
  // lies on one side of it: side = +1 after it (camera rays), -1 before it (shadow rays
  // toward a point light, whose apex is the light).
  Vec3d apex;
  double apex_t = 0;
  int side = 1;
  double t_min = 0, t_max = 0;
  // Pencil: each mask point's direction D(u, v); parallel: its origin O(u, v).
  std::array<Vec3d, kMaskSide * kMaskSide> point;
  // The four side planes of the volume the sub-rays sweep (u = -1/2, +1/2, v = -1/2, +1/2): a
  // point X is on the footprint's side of plane k when dot(side_normal[k], X - side_point[k])
  // >= 0. A convex piece with every corner strictly outside one of them covers nothing: the
  // cheapest rejection of the pieces a walk's box test lets in (a zero normal rejects nothing).
  std::array<Vec3d, 4> side_normal{}, side_point{};
  bool outside_a_side(std::span<const Vec3f> corners) const;

  // False for a General footprint, one without differentials, a non-finite ray, or a pencil
  // whose apex lies inside the ray's interval.
  static bool make(const Ray& ray, const RayFootprint& footprint, FootprintFrame& out);

  Vec3d direction(double u, double v) const { return d + ddx * u + ddy * v; }
  Vec3d origin(double u, double v) const { return o + dox * u + doy * v; }
};

}  // namespace darc
