#include "ri/basis_steps.h"

namespace darc {

void BasisSteps::basis(const BasisArg& ubasis, int ustep, const BasisArg& vbasis, int vstep, const SourceLoc& loc) {
  ForwardingTarget::basis(ubasis, ustep, vbasis, vstep, loc);
  if (ustep > 0 && vstep > 0) steps_.back() = Steps{ustep, vstep};
}

void BasisSteps::attribute_begin(const SourceLoc& loc) {
  ForwardingTarget::attribute_begin(loc);
  push();
}

void BasisSteps::attribute_end(const SourceLoc& loc) {
  ForwardingTarget::attribute_end(loc);
  if (steps_.size() > 1) steps_.pop_back();
}

// An object's requests are recorded, not applied: a Basis inside one does not last.
void BasisSteps::object_begin(const std::string& handle, const SourceLoc& loc) {
  ForwardingTarget::object_begin(handle, loc);
  push();
}

void BasisSteps::object_end(const SourceLoc& loc) {
  ForwardingTarget::object_end(loc);
  if (steps_.size() > 1) steps_.pop_back();
}

void BasisSteps::frame_begin(int number, const SourceLoc& loc) {
  ForwardingTarget::frame_begin(number, loc);
  push();
  frame_depths_.push_back(steps_.size());
}

void BasisSteps::frame_end(const SourceLoc& loc) {
  ForwardingTarget::frame_end(loc);
  if (frame_depths_.empty()) return;
  close_to(frame_depths_.back());
  frame_depths_.pop_back();
}

void BasisSteps::world_begin(const SourceLoc& loc) {
  ForwardingTarget::world_begin(loc);
  push();
  world_depths_.push_back(steps_.size());
}

void BasisSteps::world_end(const SourceLoc& loc) {
  ForwardingTarget::world_end(loc);
  if (world_depths_.empty()) return;
  close_to(world_depths_.back());
  world_depths_.pop_back();
}

}  // namespace darc
