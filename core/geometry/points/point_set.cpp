#include "core/geometry/points/point_set.h"

#include <cmath>

namespace darc {

BBox PointSet::bounds(size_t i) const {
  const float r = radius[i];
  const Vec3f e{r, r, r};
  BBox box;
  box.extend(center[i] - e);
  box.extend(center[i] + e);
  return box;
}

void PointSet::add(const Vec3f& centre, float r, uint32_t m, const PointShading& s) {
  if (shading.empty() || !(shading.back() == s)) shading.push_back(s);
  center.push_back(centre);
  radius.push_back(r);
  material.push_back(m);
  shading_index.push_back(uint32_t(shading.size() - 1));
}

void PointSet::shrink_to_fit() {
  center.shrink_to_fit();
  radius.shrink_to_fit();
  material.shrink_to_fit();
  shading_index.shrink_to_fit();
  shading.shrink_to_fit();
}

size_t PointSet::memory_bytes() const {
  return center.capacity() * sizeof(Vec3f) + radius.capacity() * sizeof(float) +
         material.capacity() * sizeof(uint32_t) + shading_index.capacity() * sizeof(uint32_t) +
         shading.capacity() * sizeof(PointShading);
}

bool intersect_point(const PointSet& set, size_t i, const Ray& ray, float& t) {
  const float r = set.radius[i];
  if (!(r > 0.0f)) return false;
  const float dd = dot(ray.d, ray.d);
  if (!(dd > 0.0f) || !std::isfinite(dd)) return false;
  const Vec3f rel = set.center[i] - ray.o;
  const float t_centre = dot(rel, ray.d) / dd;
  if (!(t_centre > ray.tmin && t_centre < ray.tmax)) return false;
  // The squared distance from the centre to the ray, |rel|^2 - (its part along d)^2, computed as
  // the length of the perpendicular part (no cancellation when the centre is far along the ray).
  const Vec3f across = rel - ray.d * t_centre;
  if (!(length_squared(across) <= r * r)) return false;
  t = t_centre;
  return true;
}

}  // namespace darc
