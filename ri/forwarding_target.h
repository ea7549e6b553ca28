// An RiTarget that passes every request on to another one: the base of a target that watches
// the request stream (the RI bindings keep the current basis steps from it: basis_steps.h) without
// taking part in it.
#pragma once

#include "parser/ri_target.h"

namespace darc {

class ForwardingTarget : public RiTarget {
 public:
  explicit ForwardingTarget(RiTarget& next) : next_(next) {}

  void replayed_request(uint64_t id) override { next_.replayed_request(id); }
  ProceduralBound procedural_bound(const std::array<double, 6>& bound, const SourceLoc& loc) override {
    return next_.procedural_bound(bound, loc);
  }
#define DARC_RI_REQUEST(Rib, method, reading, shape, args) \
  void method(DARC_RI_PARAMS(args) const SourceLoc& loc) override { next_.method(DARC_RI_NAMES(args) loc); }
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args)                     \
  void method(DARC_RI_PARAMS(args) const ParamList& params, const SourceLoc& loc) override { \
    next_.method(DARC_RI_NAMES(args) params, loc);                               \
  }
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL

 private:
  RiTarget& next_;
};

}  // namespace darc
