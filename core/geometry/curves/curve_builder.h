// Turns one RiCurves call (already parsed and typed) into cubic Bézier segments of a CurveSet:
// validation of the counts, basis conversion in object space, transform to world space.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/math/curve_basis.h"
#include "core/geometry/curves/curve_set.h"
#include "core/math/matrix.h"
#include "core/math/vec.h"
#include "parser/param_list.h"

namespace darc {

// One primitive variable as given in the parameter list: `components` floats per value.
struct PrimvarInput {
  StorageClass storage = StorageClass::Vertex;
  std::vector<float> values;
  int components = 1;
};

struct CurvesInput {
  bool cubic = true;
  bool periodic = false;
  std::vector<int> nvertices;
  CurveBasis basis = bezier_basis();  // used only when cubic (the current RiBasis v basis and vstep)
  std::vector<float> P;
  int p_components = 3;  // 3 for "P", 4 for "Pw" (divided by w: curves are not rational)
  std::optional<PrimvarInput> width;
  std::optional<float> constantwidth;  // used when `width` is absent; the default width is 1.0
  std::optional<PrimvarInput> N;       // present: oriented ribbons; absent: ribbons facing the ray
  std::optional<PrimvarInput> Cs, Os;
  // Texture coordinates: "st" (2 numbers per value), else "s" and "t" (1 each; a missing one is 0).
  std::optional<PrimvarInput> st, s, t;
  Vec3f default_cs{1, 1, 1}, default_os{1, 1, 1};  // the current Color / Opacity attributes
  Matrix4 object_to_world;
};

// The shape of a Curves call, enough to count segments and primvar values.
struct CurvesTopology {
  bool cubic = true;
  bool periodic = false;
  int step = 3;  // the basis vstep for cubic curves; ignored for linear curves
  std::span<const int> nvertices;
};

// Throws RibError unless every curve has a valid vertex count for its type, wrap and step.
void validate_topology(const CurvesTopology& topology);
// Segments of one curve with nv vertices (nv already validated).
size_t segments_in_curve(const CurvesTopology& topology, int nv);
// Number of values (not floats) a primvar of the given class must have (RISpec Curves table;
// facevarying is accepted with the varying count, facevertex with the vertex count).
// Requires a validated topology.
size_t expected_count(StorageClass storage, const CurvesTopology& topology);

// What append_curves left out besides collapsed segments: segments whose world-space control
// points or widths overflow float (finite input, a large transform), for the caller to report.
struct CurvesAppended {
  size_t segments_beyond_float_range = 0;
  size_t first_curve_beyond = 0;  // index of the curve holding the first of them
};

// Validates `input` (throws RibError with the offending name and counts before allocating
// anything sized from it), then appends its segments to `set`. Each curve gets the strand id
// next_strand_id++. Segments whose control points all coincide are dropped, and so are segments
// beyond the float range in world space (counted in the result).
CurvesAppended append_curves(CurveSet& set, const CurvesInput& input, uint32_t attribute_id, uint32_t& next_strand_id);

}  // namespace darc
