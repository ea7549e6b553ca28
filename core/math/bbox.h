// Axis-aligned bounding boxes (float, world space).
#pragma once

#include "core/math/ray.h"
#include "core/math/vec.h"

#include <algorithm>
#include <limits>

namespace darc {

struct BBox {
  Vec3f lo{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
           std::numeric_limits<float>::infinity()};
  Vec3f hi{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
           -std::numeric_limits<float>::infinity()};

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void extend(const Vec3f& p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void extend(const BBox& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
  // Grows the box by r in every direction.
  BBox expanded(float r) const { return {lo - Vec3f{r, r, r}, hi + Vec3f{r, r, r}}; }
  Vec3f extent() const { return hi - lo; }
  Vec3f center() const { return (lo + hi) * 0.5f; }

  // Slab test. On a hit, [t0, t1] is the overlap of the ray's interval with the box.
  bool intersect(const Ray& ray, float& t0, float& t1) const {
    t0 = ray.tmin;
    t1 = ray.tmax;
    for (int a = 0; a < 3; ++a) {
      float inv = 1.0f / ray.d[a];
      float tn = (lo[a] - ray.o[a]) * inv;
      float tf = (hi[a] - ray.o[a]) * inv;
      if (tn > tf) std::swap(tn, tf);
      // NaN-safe: a NaN from 0*inf leaves t0/t1 unchanged.
      t0 = tn > t0 ? tn : t0;
      t1 = tf < t1 ? tf : t1;
      if (t0 > t1) return false;
    }
    return true;
  }
};

}  // namespace darc
