// Random boxes and footprint rays, and the brute-force "within reach" scan, shared by the tests
// of the two footprint walks (the grid's and the BVH's) so both are held to the same promise.
#pragma once

#include <algorithm>
#include <random>
#include <vector>

#include "core/math/bbox.h"
#include "core/math/ray.h"
#include "core/footprint/ray_footprint.h"

namespace darc::test {

// Steps of the brute-force scan along the ray (over [tmin, kScanLength]).
inline constexpr int kScanSteps = 2000;
inline constexpr float kScanLength = 60.0f;
// A box counts as "within reach" only with this margin, so that the brute force's float
// rounding never decides a test.
inline constexpr double kReachMargin = 1e-3;

inline double box_distance(const BBox& b, const Vec3d& p) {
  Vec3d lo(b.lo), hi(b.hi);
  Vec3d q{std::clamp(p.x, lo.x, hi.x), std::clamp(p.y, lo.y, hi.y), std::clamp(p.z, lo.z, hi.z)};
  return length(p - q);
}

// The smallest scanned t at which the box is within the footprint reach of the ray (the reach an
// acceleration walk uses, RayFootprint::walk_reach_bound), or -1.
inline double first_t_within_reach(const BBox& b, const Ray& ray, const RayFootprint& fp) {
  for (int i = 0; i <= kScanSteps; ++i) {
    double t = double(ray.tmin) + (kScanLength - ray.tmin) * i / kScanSteps;
    if (t > ray.tmax) break;
    if (box_distance(b, Vec3d(ray.o) + Vec3d(ray.d) * t) <= fp.walk_reach_bound().at(float(t)) - kReachMargin)
      return t;
  }
  return -1;
}

// `count` boxes up to 1.2 on a side in [0, 10]^3.
inline std::vector<BBox> random_boxes(std::mt19937& rng, int count) {
  std::uniform_real_distribution<float> pos(0.0f, 10.0f), size(0.0f, 1.2f);
  std::vector<BBox> boxes;
  for (int i = 0; i < count; ++i) {
    Vec3f lo{pos(rng), pos(rng), pos(rng)};
    boxes.push_back(BBox{lo, lo + Vec3f{size(rng), size(rng), size(rng)}});
  }
  return boxes;
}

// A ray from around the boxes towards a point among them, with a footprint that starts at up to
// 0.1 and grows by up to 0.06 per unit of t (a wide perspective cone).
inline void random_ray(std::mt19937& rng, Ray& ray, RayFootprint& fp) {
  std::uniform_real_distribution<float> around(-6.0f, 16.0f), inside(0.0f, 10.0f), small(-0.05f, 0.05f),
      growth(-0.03f, 0.03f);
  ray.o = Vec3f{around(rng), around(rng), around(rng)};
  Vec3f target{inside(rng), inside(rng), inside(rng)};
  ray.d = normalize(target - ray.o);
  fp.dox = Vec3f{small(rng), small(rng), 0};
  fp.doy = Vec3f{0, small(rng), small(rng)};
  fp.ddx = Vec3f{growth(rng), growth(rng), 0};
  fp.ddy = Vec3f{growth(rng), 0, growth(rng)};
}

}  // namespace darc::test
