// Working memory of the rays a tile traces, one level per ray depth: the camera ray's A-buffer
// and traversal state stay intact while a ray traced from inside its shading (a shadow or a
// reflection ray) uses the next level. Levels are made on first use and kept for the tile.
#pragma once

#include "core/accel/accelerator.h"
#include "integrator/abuffer.h"

#include <deque>

namespace darc {

struct RayScratch {
  TraversalScratch traversal;
  ABuffer abuffer;
};

class RayScratchStack {
 public:
  explicit RayScratchStack(const Accelerator& accel) : accel_(accel) {}

  // The scratch of ray depth `depth` (0: camera rays). A deque: references to lower levels stay
  // valid while deeper ones are added.
  RayScratch& at(size_t depth) {
    while (levels_.size() <= depth) levels_.push_back(RayScratch{accel_.make_scratch(), ABuffer{}});
    return levels_[depth];
  }

 private:
  const Accelerator& accel_;
  std::deque<RayScratch> levels_;
};

}  // namespace darc
