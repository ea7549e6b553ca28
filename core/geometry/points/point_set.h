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
#include <vector>

#include "core/math/bbox.h"
#include "core/math/ray.h"
#include "core/math/vec.h"

namespace darc {

// A point's colour (Cs) and opacity (Os).
struct PointShading {
  Vec3f cs{1, 1, 1};
  Vec3f os{1, 1, 1};
  bool operator==(const PointShading&) const = default;
};

struct PointSet {
  std::vector<Vec3f> center;            // world space
  std::vector<float> radius;            // world space, half the RI width; 0: nothing drawn
  std::vector<uint32_t> material;       // index into Scene::materials
  std::vector<uint32_t> shading_index;  // per point: its entry in `shading`
  std::vector<PointShading> shading;    // distinct colours and opacities

  size_t size() const { return center.size(); }
  bool empty() const { return center.empty(); }
  // The cube around the disc (it may face any way).
  BBox bounds(size_t i) const;
  const Vec3f& color(size_t i) const { return shading[shading_index[i]].cs; }
  const Vec3f& opacity(size_t i) const { return shading[shading_index[i]].os; }

  // Appends one point; its shading shares the previous point's entry when equal.
  void add(const Vec3f& centre, float radius, uint32_t material, const PointShading& shading = {});
  // Releases the slack the arrays grew with while points were appended.
  void shrink_to_fit();
  // Bytes held (capacity), for the memory report.
  size_t memory_bytes() const;
};

// The exact hit of point i by `ray`: the disc through its centre perpendicular to the ray's
// direction. Hit when the ray passes within the radius of the centre with the centre's
// projection t in (ray.tmin, ray.tmax); false for radius 0 and for non-finite or zero rays.
bool intersect_point(const PointSet& set, size_t i, const Ray& ray, float& t);

}  // namespace darc
