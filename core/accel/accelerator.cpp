#include "core/accel/accelerator.h"

namespace darc {

std::string to_string(AcceleratorKind kind) { return kind == AcceleratorKind::Bvh ? "bvh" : "grid"; }

Accelerator Accelerator::build(AcceleratorKind kind, std::span<const BBox> prim_bounds) {
  Accelerator a;
  a.kind_ = kind;
  if (kind == AcceleratorKind::Bvh)
    a.bvh_ = Bvh::build(prim_bounds);
  else
    a.grid_ = UniformGrid::build(prim_bounds);
  return a;
}

size_t Accelerator::memory_bytes() const {
  if (kind_ == AcceleratorKind::Bvh) return bvh_.memory_bytes();
  return (grid_.cell_offsets().size() + grid_.cell_prims().size()) * sizeof(uint32_t);
}

TraversalScratch Accelerator::make_scratch() const {
  TraversalScratch s;
  if (kind_ == AcceleratorKind::Grid) s.mailbox = Mailbox(grid_.primitive_count());
  return s;
}

}  // namespace darc
