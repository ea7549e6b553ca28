// Footprint-aware traversal of the uniform grid (after the slice-based packet traversal of
// Wald et al. 2006, as the seed paper uses it): the ray is walked one layer of cells at a time
// along its major axis; in each layer every cell within the ray's footprint reach is visited,
// so strands that pass beside the ray (not only through it) are found.
#pragma once

#include "core/math/ray.h"
#include "core/footprint/ray_footprint.h"
#include "core/accel/uniform_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace darc {

struct CellRange {
  std::array<int, 3> lo{0, 0, 0}, hi{-1, -1, -1};  // inclusive; empty when any hi < lo
  bool empty() const { return hi[0] < lo[0] || hi[1] < lo[1] || hi[2] < lo[2]; }
  bool contains(int x, int y, int z) const {
    return x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1] && z >= lo[2] && z <= hi[2];
  }
};

// The cells of `grid` overlapped by the box [lo, hi] (world), clamped to the grid.
inline CellRange cells_overlapping(const UniformGrid& grid, const Vec3d& lo, const Vec3d& hi) {
  CellRange r;
  Vec3d o = grid.origin(), cs = grid.cell_size();
  std::array<int, 3> res = grid.resolution();
  for (int a = 0; a < 3; ++a) {
    double l = std::floor((lo[a] - o[a]) / cs[a]), h = std::floor((hi[a] - o[a]) / cs[a]);
    if (!(h >= 0) || !(l < res[a])) return CellRange{};  // also catches NaN
    r.lo[a] = int(std::max(l, 0.0));
    r.hi[a] = int(std::min(h, double(res[a] - 1)));
  }
  return r;
}

// Walks the layers of cells along the ray's major axis, front to back. For each layer:
//   visit_cell(std::span<const uint32_t> prims) for every non-empty cell within the footprint
//   reach of the ray's part in that layer (cells already visited for the previous layer are
//   skipped), then
//   layer_done(float t_final) -> bool: every primitive whose closest approach to the ray lies
//   at t <= t_final has now been visited; return false to stop.
// Returns the number of cells visited.
template <class VisitCell, class LayerDone>
uint64_t traverse_with_footprint(const UniformGrid& grid, const Ray& ray, const RayFootprint& footprint,
                                 VisitCell&& visit_cell, LayerDone&& layer_done) {
  if (grid.empty()) return 0;
  Vec3d o(ray.o), d(ray.d);
  double dlen = length(d);
  if (!(dlen > 0) || !std::isfinite(dlen)) return 0;
  // The farthest the footprint can reach inside the grid: its largest reach from the ray's start
  // to the grid's far corner (the reach is convex in t: the largest is at an end).
  BBox gb = grid.bounds();
  double far_t = 0;
  for (int c = 0; c < 8; ++c) {
    Vec3d corner{(c & 1) ? gb.hi.x : gb.lo.x, (c & 2) ? gb.hi.y : gb.lo.y, (c & 4) ? gb.hi.z : gb.lo.z};
    far_t = std::max(far_t, length(corner - o) / dlen);
  }
  const ReachBound bound = footprint.walk_reach_bound();
  float max_reach = bound.max_over(std::max(0.0f, ray.tmin), float(std::min(far_t, double(ray.tmax))));
  float t0, t1;
  if (!gb.expanded(max_reach).intersect(ray, t0, t1)) return 0;

  int k = 0;  // major axis
  for (int a = 1; a < 3; ++a)
    if (std::abs(d[a]) > std::abs(d[k])) k = a;
  const double ok = grid.origin()[k], csk = grid.cell_size()[k];
  const int resk = grid.resolution()[k];
  auto layer_of = [&](double t) {
    double l = std::floor((o[k] + d[k] * t - ok) / csk);
    return int(std::clamp(l, -1.0, double(resk)));
  };
  const int step = d[k] > 0 ? 1 : -1;
  const int first = layer_of(t0), last = layer_of(t1);
  CellRange previous;
  uint64_t visited = 0;
  double ta = t0;
  for (int layer = first;; layer += step) {
    // Where the ray leaves this layer (the plane between it and the next).
    double tb = t1;
    if (layer != last) {
      double plane = ok + csk * (step > 0 ? layer + 1 : layer);
      tb = std::clamp((plane - o[k]) / d[k], ta, double(t1));
    }
    float reach = bound.max_over(float(std::max(0.0, ta)), float(std::max(0.0, tb)));
    Vec3d pa = o + d * ta, pb = o + d * tb;
    Vec3d r{reach, reach, reach};
    CellRange cells = cells_overlapping(grid, min(pa, pb) - r, max(pa, pb) + r);
    if (!cells.empty()) {
      for (int z = cells.lo[2]; z <= cells.hi[2]; ++z)
        for (int y = cells.lo[1]; y <= cells.hi[1]; ++y)
          for (int x = cells.lo[0]; x <= cells.hi[0]; ++x) {
            if (previous.contains(x, y, z)) continue;
            std::span<const uint32_t> prims = grid.cell(grid.cell_index(x, y, z));
            ++visited;
            if (!prims.empty()) visit_cell(prims);
          }
      previous = cells;
    }
    if (!layer_done(float(tb)) || layer == last) break;
    ta = tb;
  }
  return visited;
}

}  // namespace darc
