// Every RI Points particle of a scene: discs in world space that face the ray (RI spec 3.2
// §5.6: "Points" are flat discs of diameter "width", always perpendicular to the eye). Like
// strands they are usually far smaller than a pixel, so the distance hider takes them as
// sub-pixel primitives with coverage and masks (core/geometry/points/point_set_coverage.h); the stochastic hider
// hits them exactly here.
//
// What a point costs: 12 bytes of centre, 4 of radius, 4 of material, 4 of shading index; colour
// and opacity are stored once per distinct value (a Points call without Cs/Os shares one entry).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math/bbox.h"
#include "core/math/ray.h"
#include "core/math/vec.h"

namespace darc {

// A point's colour (Cs), opacity (Os) and texture coordinates (st: a point is one texel).
struct PointShading {
  Vec3f cs{1, 1, 1};
  Vec3f os{1, 1, 1};
  Vec2f st{};
  bool operator==(const PointShading&) const = default;
};

struct PointSet {
  std::vector<Vec3f> center;            // world space
  std::vector<float> radius;            // world space, half the RI width; 0: nothing drawn
  std::vector<uint32_t> material;       // index into Scene::materials
  std::vector<uint32_t> shading_index;  // per point: its entry in `shading`
  std::vector<PointShading> shading;    // distinct colours and opacities

  // Motion blur: per point, an index into `motions` or kStillPoint (empty while none moves). A
  // moving point's key k (at shutter time motion_times[times + k], 0 at open, 1 at close) has
  // its centre and radius at motion_center[first + k], motion_radius[first + k]; between keys
  // they move linearly. `center` and `radius` hold the point at shutter open.
  static constexpr uint32_t kStillPoint = 0xffffffffu;
  struct PointMotion {
    uint32_t times = 0, keys = 0, first = 0;
  };
  std::vector<uint32_t> motion;
  std::vector<PointMotion> motions;
  std::vector<float> motion_times;
  std::vector<Vec3f> motion_center;
  std::vector<float> motion_radius;

  bool has_motion() const { return !motions.empty(); }
  bool moving(size_t i) const { return !motion.empty() && motion[i] != kStillPoint; }
  Vec3f center_at(size_t i, float time) const;
  float radius_at(size_t i, float time) const;
  // Key times shared by the points of one request (increasing from 0 to 1): their offset, for
  // set_motion.
  uint32_t add_motion_times(std::span<const float> times);
  // Makes point i move through the given keys (as many as the times at `times`); keys that all
  // agree leave it still.
  void set_motion(size_t i, uint32_t times, std::span<const Vec3f> centers, std::span<const float> radii);

  size_t size() const { return center.size(); }
  bool empty() const { return center.empty(); }
  // The cube around the disc (it may face any way), over the whole shutter.
  BBox bounds(size_t i) const;
  const Vec3f& color(size_t i) const { return shading[shading_index[i]].cs; }
  const Vec3f& opacity(size_t i) const { return shading[shading_index[i]].os; }
  const Vec2f& texture_coordinates(size_t i) const { return shading[shading_index[i]].st; }

  // Appends one point; its shading shares the previous point's entry when equal.
  void add(const Vec3f& centre, float radius, uint32_t material, const PointShading& shading = {});
  // Releases the slack the arrays grew with while points were appended.
  void shrink_to_fit();
  // Bytes held (capacity), for the memory report.
  size_t memory_bytes() const;
};

// The exact hit of point i by `ray` (where the point is at ray.time): the disc through its centre
// perpendicular to the ray's
// direction. Hit when the ray passes within the radius of the centre with the centre's
// projection t in (ray.tmin, ray.tmax); false for radius 0 and for non-finite or zero rays.
bool intersect_point(const PointSet& set, size_t i, const Ray& ray, float& t);

}  // namespace darc
