// A uniform grid over primitive bounding boxes: the acceleration structure that curve
// segments, spheres and polygons share. Cells keep their primitive lists in one compact CSR
// layout (offsets + indices), and rays walk the cells front to back with a 3D-DDA
// (Amanatides & Woo 1987). Traversal arithmetic is in double, so that cell boundaries agree
// with the build to far below the insertion padding even for rays that start far away.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math/bbox.h"
#include "core/math/ray.h"
#include "core/math/vec.h"

namespace darc {

// The state of one ray's walk through the grid's cells (3D-DDA).
struct GridWalk {
  std::array<int, 3> cell{};        // current cell coordinates
  std::array<int, 3> step{};        // +1, -1 or 0 per axis
  std::array<double, 3> t_next{};   // ray t where the walk leaves the current cell along each axis
  std::array<double, 3> t_delta{};  // ray t needed to cross one cell along each axis
  double t_enter = 0;               // ray t where the walk entered the current cell
  double t_end = 0;                 // ray t where the walk leaves the grid or the ray ends
};

class UniformGrid {
 public:
  // An empty grid: traversal visits nothing.
  UniformGrid() = default;

  // Builds the grid over prim_bounds[i] for primitive index i. Empty boxes and boxes with a
  // non-finite coordinate are left out (never reported). Cell lists hold indices in
  // increasing order, so traversal is deterministic.
  static UniformGrid build(std::span<const BBox> prim_bounds);

  bool empty() const { return cell_prims_.empty(); }
  // The number of boxes given to build() (the size a Mailbox needs).
  uint32_t primitive_count() const { return primitive_count_; }

  std::array<int, 3> resolution() const { return res_; }
  Vec3d cell_size() const { return cell_size_; }
  Vec3d origin() const { return origin_; }  // lower corner of cell (0, 0, 0)
  BBox bounds() const { return bounds_; }   // the grid's (padded) extent
  uint32_t cell_index(int ix, int iy, int iz) const {
    return (uint32_t(iz) * uint32_t(res_[1]) + uint32_t(iy)) * uint32_t(res_[0]) + uint32_t(ix);
  }
  uint32_t cell_count() const { return uint32_t(res_[0]) * uint32_t(res_[1]) * uint32_t(res_[2]); }
  // CSR layout: the primitives of cell c are cell_prims()[cell_offsets()[c] .. cell_offsets()[c+1]).
  std::span<const uint32_t> cell_offsets() const { return cell_offsets_; }
  std::span<const uint32_t> cell_prims() const { return cell_prims_; }
  std::span<const uint32_t> cell(uint32_t index) const {
    return std::span<const uint32_t>(cell_prims_)
        .subspan(cell_offsets_[index], cell_offsets_[index + 1] - cell_offsets_[index]);
  }
  // Cell coordinates containing p, clamped to the grid.
  std::array<int, 3> cell_of(const Vec3d& p) const;

  // Starts a walk over [ray.tmin, ray.tmax] clipped to the grid; false when the ray misses the
  // grid, has a zero or NaN direction, or the grid is empty.
  bool begin_walk(const Ray& ray, GridWalk& walk) const;

  // Calls visit(std::span<const uint32_t> prims, float t_enter, float t_exit) for every
  // non-empty cell the ray passes through, front to back (t_enter never decreases); stops when
  // visit returns false. A primitive spanning several cells is reported once per cell: use a
  // Mailbox to test it once per ray.
  template <class Visit>
  void traverse(const Ray& ray, Visit&& visit) const {
    GridWalk walk;
    if (!begin_walk(ray, walk)) return;
    for (;;) {
      int axis = walk.t_next[0] < walk.t_next[1] ? (walk.t_next[0] < walk.t_next[2] ? 0 : 2)
                                                 : (walk.t_next[1] < walk.t_next[2] ? 1 : 2);
      double t_exit = std::max(std::min(walk.t_next[axis], walk.t_end), walk.t_enter);
      std::span<const uint32_t> prims = cell(cell_index(walk.cell[0], walk.cell[1], walk.cell[2]));
      if (!prims.empty() && !visit(prims, float(walk.t_enter), float(t_exit))) return;
      if (t_exit >= walk.t_end) return;
      walk.cell[axis] += walk.step[axis];
      if (walk.cell[axis] < 0 || walk.cell[axis] >= res_[axis]) return;
      walk.t_enter = t_exit;
      walk.t_next[axis] += walk.t_delta[axis];
    }
  }

 private:
  // The cell coordinate range [lo, hi] overlapped by box (widened by the insertion padding).
  void cell_range(const BBox& box, std::array<int, 3>& lo, std::array<int, 3>& hi) const;

  std::array<int, 3> res_{1, 1, 1};
  Vec3d origin_;
  Vec3d cell_size_{1, 1, 1};
  Vec3d inv_cell_size_{1, 1, 1};
  BBox bounds_;
  uint32_t primitive_count_ = 0;
  std::vector<uint32_t> cell_offsets_{0, 0};  // one cell, empty
  std::vector<uint32_t> cell_prims_;
};

// Makes sure each primitive is tested once per ray although the grid reports it once per
// cell: a stamp per primitive holds the number of the last ray that saw it. Per ray the cost is
// O(1) (a counter increment; a full clear once every 2^32 rays); memory is 4 bytes per
// primitive, so keep one Mailbox per thread and reuse it for every ray.
class Mailbox {
 public:
  explicit Mailbox(size_t primitive_count) : stamps_(primitive_count, 0) {}

  // Starts a new ray: every primitive counts as unseen again.
  void next_ray() {
    if (++ray_ == 0) {  // wrapped: old stamps could collide with new ray numbers
      std::fill(stamps_.begin(), stamps_.end(), 0u);
      ray_ = 1;
    }
  }

  // True the first time prim is seen since next_ray(), false afterwards.
  bool first_visit(uint32_t prim) {
    if (stamps_[prim] == ray_) return false;
    stamps_[prim] = ray_;
    return true;
  }

 private:
  std::vector<uint32_t> stamps_;
  uint32_t ray_ = 1;
};

}  // namespace darc
