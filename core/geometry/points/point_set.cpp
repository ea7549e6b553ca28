#include "core/geometry/points/point_set.h"

#include "core/math/motion_keys.h"

#include <algorithm>
#include <cmath>

namespace darc {

BBox PointSet::bounds(size_t i) const {
  const float r = radius[i];
  const Vec3f e{r, r, r};
  BBox box;
  box.extend(center[i] - e);
  box.extend(center[i] + e);
  if (moving(i)) {
    // Centres and radii move linearly between keys: the keys' cubes bound the whole shutter.
    const PointMotion& m = motions[motion[i]];
    for (uint32_t k = 0; k < m.keys; ++k) {
      const float rk = motion_radius[m.first + k];
      box.extend(motion_center[m.first + k] - Vec3f{rk, rk, rk});
      box.extend(motion_center[m.first + k] + Vec3f{rk, rk, rk});
    }
  }
  return box;
}

Vec3f PointSet::center_at(size_t i, float time) const {
  if (!moving(i)) return center[i];
  const PointMotion& m = motions[motion[i]];
  uint32_t k;
  float s;
  key_interval(&motion_times[m.times], m.keys, time, k, s);
  const Vec3f& a = motion_center[m.first + k];
  const Vec3f& b = motion_center[m.first + k + 1];
  return s == 0.0f ? a : s == 1.0f ? b : a + (b - a) * s;
}

float PointSet::radius_at(size_t i, float time) const {
  if (!moving(i)) return radius[i];
  const PointMotion& m = motions[motion[i]];
  uint32_t k;
  float s;
  key_interval(&motion_times[m.times], m.keys, time, k, s);
  const float a = motion_radius[m.first + k], b = motion_radius[m.first + k + 1];
  return a + (b - a) * s;
}

uint32_t PointSet::add_motion_times(std::span<const float> times) {
  const uint32_t offset = uint32_t(motion_times.size());
  motion_times.insert(motion_times.end(), times.begin(), times.end());
  return offset;
}

void PointSet::set_motion(size_t i, uint32_t times, std::span<const Vec3f> centers, std::span<const float> radii) {
  if (centers.size() < 2 || radii.size() != centers.size()) return;
  bool still = true;
  for (size_t k = 1; k < centers.size(); ++k)
    still = still && centers[k].x == centers[0].x && centers[k].y == centers[0].y && centers[k].z == centers[0].z &&
            radii[k] == radii[0];
  if (still) return;
  motion.resize(center.size(), kStillPoint);
  motion[i] = uint32_t(motions.size());
  motions.push_back({times, uint32_t(centers.size()), uint32_t(motion_center.size())});
  motion_center.insert(motion_center.end(), centers.begin(), centers.end());
  motion_radius.insert(motion_radius.end(), radii.begin(), radii.end());
}

void PointSet::add(const Vec3f& centre, float r, uint32_t m, const PointShading& s) {
  if (shading.empty() || !(shading.back() == s)) shading.push_back(s);
  center.push_back(centre);
  radius.push_back(r);
  material.push_back(m);
  shading_index.push_back(uint32_t(shading.size() - 1));
  if (!motion.empty()) motion.push_back(kStillPoint);
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
         shading.capacity() * sizeof(PointShading) + motion.capacity() * sizeof(uint32_t) +
         motions.capacity() * sizeof(PointMotion) + motion_times.capacity() * sizeof(float) +
         motion_center.capacity() * sizeof(Vec3f) + motion_radius.capacity() * sizeof(float);
}

bool intersect_point(const PointSet& set, size_t i, const Ray& ray, float& t) {
  const bool moves = set.moving(i);
  const float r = moves ? set.radius_at(i, ray.time) : set.radius[i];
  if (!(r > 0.0f)) return false;
  const float dd = dot(ray.d, ray.d);
  if (!(dd > 0.0f) || !std::isfinite(dd)) return false;
  const Vec3f rel = (moves ? set.center_at(i, ray.time) : set.center[i]) - ray.o;
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
