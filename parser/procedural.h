// The Procedural and Procedural2 requests, read and checked: which built-in procedural is asked
// for, its string arguments and its bound. RibParser expands them (rib_parser_procedural.cpp).
//   Procedural "DelayedReadArchive" ["file.rib"] [xmin xmax ymin ymax zmin zmax]     (RI Spec 3.2)
//   Procedural "RunProgram" ["program args" "data"] [bound]
//   Procedural "DynamicLoad" ["library" "data"] [bound]
//   Procedural2 "DelayedReadArchive2" "SimpleBound" "string filename" ["file.rib"] "float[6] bound" [...]
//                                                                              (RenderMan 21 and later)
#pragma once

#include <array>
#include <string>
#include <vector>

#include "parser/request_reader.h"

namespace darc {

enum class ProceduralKind { DelayedReadArchive, RunProgram, DynamicLoad, Unknown };

struct ProceduralCall {
  ProceduralKind kind = ProceduralKind::Unknown;
  std::string type;  // as written: "DelayedReadArchive", "DelayedReadArchive2", "RunProgram", ...
  // DelayedReadArchive: {file}; RunProgram: {program and its arguments, data}; DynamicLoad:
  // {library, data}; Unknown: as written.
  std::vector<std::string> strings;
  std::array<double, 6> bound{};  // xmin xmax ymin ymax zmin zmax, in the current object space
};

// Reads the arguments of `request` ("Procedural" or "Procedural2"). Throws RibSyntaxError at the
// offending token for malformed arguments, RibError for a wrong count of strings or a bound whose
// minimum exceeds its maximum.
ProceduralCall read_procedural(RequestReader& args, const std::string& request);

}  // namespace darc
