// The current Basis steps, kept from the request stream as the attribute blocks open and close:
// the C binding needs them to know how many values a varying parameter of RiCurves or
// RiPatchMesh has (RI Spec 3.2 section 5: one per segment end, which the v step decides). Every
// request, those read from archives included, passes through it on its way to the target, and
// it follows the target: a request the target refuses (it throws) changes nothing here.
#pragma once

#include "ri/forwarding_target.h"

#include <algorithm>
#include <vector>

namespace darc {

class BasisSteps : public ForwardingTarget {
 public:
  explicit BasisSteps(RiTarget& next) : ForwardingTarget(next) {}

  int ustep() const { return steps_.back().u; }
  int vstep() const { return steps_.back().v; }

  void basis(const BasisArg& ubasis, int ustep, const BasisArg& vbasis, int vstep, const SourceLoc& loc) override;
  void attribute_begin(const SourceLoc& loc) override;
  void attribute_end(const SourceLoc& loc) override;
  void object_begin(const std::string& handle, const SourceLoc& loc) override;
  void object_end(const SourceLoc& loc) override;
  void frame_begin(int number, const SourceLoc& loc) override;
  void frame_end(const SourceLoc& loc) override;
  void world_begin(const SourceLoc& loc) override;
  void world_end(const SourceLoc& loc) override;

 private:
  struct Steps {
    int u = 3, v = 3;  // RI's default basis is Bezier
  };
  void push() { steps_.push_back(steps_.back()); }
  // Back to the depth before the block that opened at `depth` (blocks left open inside it close
  // with it, as the builder closes them).
  void close_to(size_t depth) {
    if (depth <= steps_.size()) steps_.resize(std::max<size_t>(depth, 2) - 1);
  }
  std::vector<Steps> steps_{Steps{}};
  std::vector<size_t> frame_depths_, world_depths_;  // the stack's size just after each opened
};

}  // namespace darc
