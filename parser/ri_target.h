// The RenderMan Interface as an abstract target: one virtual function per RI request, like the
// RenderMan C API (and pbrt's ParserTarget), derived from the one list of requests
// (parser/ri_requests.def). The RIB parser calls it; SceneBuilder (core/) builds scenes from it,
// RibWriter pretty-prints it (darc --cat), CallRecorder keeps calls to replay them.
//
// Every call carries the SourceLoc of the request name. A target reports a scene error in a
// request by throwing RibError; the parser reports it with the position and continues at the
// next request. Warnings go to the Diagnostics object the target was constructed with.
#pragma once

#include "parser/param_list.h"
#include "parser/ri_arg_kinds.h"
#include "parser/ri_request_macros.h"
#include "parser/source_loc.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace darc {

// What the frame being built makes of a procedural's bound, asked before the procedural is read
// or run (RiTarget::procedural_bound).
struct ProceduralBound {
  bool wanted = true;      // false: nothing inside it can reach an image (its frame is not rendered)
  double raster_area = 0;  // pixels the bound covers in the image (RunProgram's "detail"); 0: unknown
};

class RiTarget {
 public:
  virtual ~RiTarget() = default;

  // The parser calls this before each call it replays from its archive cache with a number
  // unique, for the run, to that recorded call, and with 0 after it: the same number means the
  // same request with the same arguments, so a target may reuse what it built from it before.
  virtual void replayed_request(uint64_t id) { (void)id; }

  // One pure virtual function per request of parser/ri_requests.def, in its order: each takes
  // the request's arguments as the list gives them, then its parameter list when it has one, then
  // the position of the request name.
#define DARC_RI_REQUEST(Rib, method, reading, shape, args) \
  virtual void method(DARC_RI_PARAMS(args) const SourceLoc& loc) = 0;
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args) \
  virtual void method(DARC_RI_PARAMS(args) const ParamList& params, const SourceLoc& loc) = 0;
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL

  // Procedurals are expanded by the parser (the target sees what they produce, inside an
  // AttributeBegin/AttributeEnd pair); this asks first about the bound (xmin xmax ymin ymax zmin
  // zmax in the current object space). The default: wanted, area unknown.
  virtual ProceduralBound procedural_bound(const std::array<double, 6>& /*bound*/, const SourceLoc& /*loc*/) {
    return {};
  }
};

// An RiTarget that does nothing with any request: the base of a target that wants only a few.
class RiTargetDefaults : public RiTarget {
 public:
#define DARC_RI_REQUEST(Rib, method, reading, shape, args) \
  void method(DARC_RI_TYPES(args) const SourceLoc&) override {}
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args) \
  void method(DARC_RI_TYPES(args) const ParamList&, const SourceLoc&) override {}
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL
};

}  // namespace darc
