// The geometric queries the hiders ask of a scene, above whichever structure culls it: the
// nearest hit of a thin ray, and the footprint walk of a ray widened by its footprint with
// "everything nearer than t has been visited" progress. A uniform grid (the seed paper's
// choice) and a BVH both sit behind them; the hiders never see which.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "core/accel/bvh.h"
#include "core/accel/footprint_traversal.h"
#include "core/accel/uniform_grid.h"

namespace darc {

enum class AcceleratorKind { Grid, Bvh };

std::string to_string(AcceleratorKind kind);

// Per-ray working memory of the queries (one per thread and ray depth: a query in progress
// must not share it with a query started from inside its callbacks).
struct TraversalScratch {
  Mailbox mailbox{0};  // grid only: each primitive tested once per ray
  BvhScratch bvh;
};

class Accelerator {
 public:
  Accelerator() = default;
  static Accelerator build(AcceleratorKind kind, std::span<const BBox> prim_bounds);

  AcceleratorKind kind() const { return kind_; }
  const UniformGrid& grid() const { return grid_; }
  const Bvh& bvh() const { return bvh_; }
  size_t memory_bytes() const;
  // Scratch sized for this structure.
  TraversalScratch make_scratch() const;

  // Nearest hit: calls test(prim, ray) for candidate primitives, roughly front to back, each
  // once; a test that hits shortens ray.tmax. Returns the number of cells or nodes visited.
  template <class Test>
  uint64_t nearest(Ray& ray, TraversalScratch& scratch, Test&& test) const {
    if (kind_ == AcceleratorKind::Bvh) return bvh_.nearest(ray, scratch.bvh, test);
    scratch.mailbox.next_ray();
    uint64_t cells = 0;
    grid_.traverse(ray, [&](std::span<const uint32_t> prims, float, float t_exit) {
      ++cells;
      for (uint32_t p : prims)
        if (scratch.mailbox.first_visit(p)) test(p, ray);
      // A hit inside this cell cannot be beaten by a later cell.
      return ray.tmax > t_exit;
    });
    return cells;
  }

  // Footprint walk: visit(prim) once for every primitive that may come within the footprint's
  // reach of the ray, front to back in steps; between steps progress(t_final) says that every
  // primitive with a part within reach at t < t_final has been visited (return false to stop).
  // visit may shorten ray.tmax (an opaque surface covering the footprint): the walk then stops
  // once t_final passes it. Returns the number of cells or nodes visited.
  template <class Visit, class Progress>
  uint64_t footprint_walk(Ray& ray, const RayFootprint& footprint, TraversalScratch& scratch, Visit&& visit,
                          Progress&& progress) const {
    if (kind_ == AcceleratorKind::Bvh) return bvh_.footprint_walk(ray, footprint, scratch.bvh, visit, progress);
    scratch.mailbox.next_ray();
    return traverse_with_footprint(
        grid_, ray, footprint,
        [&](std::span<const uint32_t> prims) {
          for (uint32_t p : prims)
            if (scratch.mailbox.first_visit(p)) visit(p);
        },
        [&](float t_final) { return progress(t_final) && t_final < ray.tmax; });
  }

 private:
  AcceleratorKind kind_ = AcceleratorKind::Grid;
  UniformGrid grid_;
  Bvh bvh_;
};

}  // namespace darc
