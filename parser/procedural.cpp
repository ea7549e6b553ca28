#include "parser/procedural.h"

#include <fmt/format.h>

#include <algorithm>

namespace darc {

namespace {

ProceduralKind kind_of(const std::string& type) {
  if (type == "DelayedReadArchive") return ProceduralKind::DelayedReadArchive;
  if (type == "RunProgram") return ProceduralKind::RunProgram;
  if (type == "DynamicLoad") return ProceduralKind::DynamicLoad;
  return ProceduralKind::Unknown;
}

ProceduralKind kind_of_procedural2(const std::string& type) {
  if (type == "DelayedReadArchive2") return ProceduralKind::DelayedReadArchive;
  if (type == "DynamicLoad") return ProceduralKind::DynamicLoad;
  return ProceduralKind::Unknown;
}

void check_bound(const std::array<double, 6>& b) {
  static constexpr std::array<char, 3> kAxes = {'x', 'y', 'z'};
  for (size_t axis = 0; axis < 3; ++axis) {
    const double lo = b[2 * axis], hi = b[2 * axis + 1];
    if (lo > hi)
      throw RibError(fmt::format("the bound's {0}min ({1}) is greater than its {0}max ({2})", kAxes[axis], lo, hi));
  }
}

// The procedurals darc skips are not held to a count: their arguments are never used.
void check_string_count(const ProceduralCall& call) {
  if (call.kind == ProceduralKind::DelayedReadArchive && call.strings.size() != 1)
    throw RibError(fmt::format("DelayedReadArchive takes one string, the file name (found {})", call.strings.size()));
  if (call.kind == ProceduralKind::RunProgram && call.strings.size() != 2)
    throw RibError(
        fmt::format("RunProgram takes two strings, the program and its data (found {})", call.strings.size()));
}

ProceduralCall read_ri_procedural(RequestReader& args) {
  ProceduralCall call;
  call.type = args.string("the procedural type");
  call.kind = kind_of(call.type);
  call.strings = args.string_array("the procedural's arguments");
  call.bound = args.numbers<6>("the bound");
  args.expect_request_end("Procedural");
  check_string_count(call);
  return call;
}

ProceduralCall read_procedural2(RequestReader& args) {
  ProceduralCall call;
  call.type = args.string("the procedural type");
  call.kind = kind_of_procedural2(call.type);
  args.string("the bound function");  // "SimpleBound": the bound is the "bound" parameter
  const ParamList params = args.param_list("Procedural2");
  const Param* bound = params.find("bound");
  if (bound && bound->floats.size() != 6)
    throw RibError(
        fmt::format("\"bound\" needs 6 numbers (xmin xmax ymin ymax zmin zmax), found {}", bound->floats.size()));
  if (bound) std::copy(bound->floats.begin(), bound->floats.end(), call.bound.begin());
  if (call.kind != ProceduralKind::DelayedReadArchive) return call;
  const Param* filename = params.find("filename");
  if (!filename || filename->strings.size() != 1)
    throw RibError(fmt::format("{} needs one \"string filename\"", call.type));
  if (!bound) throw RibError(fmt::format("{} needs \"float[6] bound\"", call.type));
  call.strings = filename->strings;
  return call;
}

}  // namespace

ProceduralCall read_procedural(RequestReader& args, const std::string& request) {
  ProceduralCall call = request == "Procedural2" ? read_procedural2(args) : read_ri_procedural(args);
  check_bound(call.bound);
  return call;
}

}  // namespace darc
