#include "core/footprint/distance_ray.h"

#include <cmath>

namespace darc {

namespace {

bool finite3(const Vec3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

DistanceRay make_distance_ray(const Ray& ray, const RayFootprint& footprint) {
  DistanceRay r;
  if (!finite3(ray.o) || !finite3(ray.d) || std::isnan(ray.tmin) || std::isnan(ray.tmax)) return r;
  // The frame in double, once per ray: it is reused for every segment.
  Vec3d dir(ray.d);
  double ray_length = length(dir);
  if (!(ray_length > 0.0) || !std::isfinite(ray_length)) return r;
  dir = dir / ray_length;
  Vec3d x, y;
  orthonormal_basis(dir, x, y);
  r.valid = true;
  r.origin = ray.o;
  r.dir = Vec3f(dir);
  r.frame_x = Vec3f(x);
  r.frame_y = Vec3f(cross(dir, x));
  r.ray_length = float(ray_length);
  r.t_min = ray.tmin;
  r.t_max = ray.tmax;
  r.time = ray.time;
  r.sweeps_shutter = ray.sweeps_shutter;
  r.sweep_from = ray.sweep_from;
  r.sweep_to = ray.sweep_to;
  r.reach = footprint.reach_bound();
  r.footprint = &footprint;
  r.depth_min = r.t_min * r.ray_length;
  if (footprint.start_half_space(ray.o, ray.d, r.start)) {
    r.has_start = true;
    r.start.offset = 0;  // relative to the origin
    const float lowest_origin = -0.5f * (std::abs(dot(footprint.dox, r.dir)) + std::abs(dot(footprint.doy, r.dir)));
    r.depth_min = std::min(r.depth_min, lowest_origin);
  }
  return r;
}

}  // namespace darc
