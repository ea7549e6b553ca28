// SceneBuilder's Attribute "Ri": RenderMan 21 and later write some RI requests as attributes
// of that category (RenderMan for Maya's hair: Attribute "Ri" "constant string[2] Basis"
// ["b-spline" "b-spline"] "constant int[2] BasisStep" [1 1]). "Basis" and "BasisStep" set the
// curve basis exactly as the Basis request does; the other names have no effect here.
#include <fmt/format.h>

#include <cmath>

#include "core/scene/builder/scene_builder.h"

namespace darc {

namespace {

// Largest step accepted: far beyond any basis (the standard ones step 1 to 4), and small enough
// to convert to int exactly.
constexpr float kMaxBasisStep = 1 << 20;

// The u and v bases of a "Basis" value: one or two names (one for both), or 16 or 32 numbers
// (one matrix for both, or u's then v's).
std::array<BasisArg, 2> basis_args(const Param& p) {
  std::array<BasisArg, 2> uv;
  if (!p.strings.empty()) {
    if (p.strings.size() > 2)
      throw RibError(fmt::format("Attribute \"Ri\" \"Basis\" takes 1 or 2 basis names, found {}", p.strings.size()));
    uv[0].name = p.strings.front();
    uv[1].name = p.strings.back();
    return uv;
  }
  if (p.floats.size() != 16 && p.floats.size() != 32)
    throw RibError(fmt::format("Attribute \"Ri\" \"Basis\" takes basis names or 16 or 32 numbers, found {} numbers",
                               p.floats.size()));
  const size_t v_begin = p.floats.size() == 32 ? 16 : 0;
  for (size_t i = 0; i < 16; ++i) {
    uv[0].matrix[i] = p.floats[i];
    uv[1].matrix[i] = p.floats[v_begin + i];
  }
  return uv;
}

// A basis as a matrix, so that a step alone can be applied to the basis in effect.
BasisArg matrix_arg(const CurveBasis& b) {
  BasisArg a;
  a.matrix = b.m;
  return a;
}

// The step a "Basis" value implies without "BasisStep": the standard one for a standard name
// (ri.h's RI_BSPLINESTEP ...), the step in effect for a matrix.
int default_step(const BasisArg& a, const CurveBasis& current) {
  if (a.name.empty()) return current.step;
  const std::optional<CurveBasis> standard = standard_basis(a.name);
  return standard ? standard->step : current.step;  // an unknown name fails in basis()
}

}  // namespace

void SceneBuilder::ri_attribute(const ParamList& params, const SourceLoc& loc) {
  const Param* basis_param = params.find("Basis");
  const Param* step_param = params.find("BasisStep");
  if (basis_param || step_param) {
    const std::array<BasisArg, 2> uv =
        basis_param ? basis_args(*basis_param)
                    : std::array<BasisArg, 2>{matrix_arg(attributes_.ubasis), matrix_arg(attributes_.vbasis)};
    int ustep = default_step(uv[0], attributes_.ubasis);
    int vstep = default_step(uv[1], attributes_.vbasis);
    if (step_param) {
      const std::vector<float>& s = step_param->floats;
      if (s.empty() || s.size() > 2)
        throw RibError(fmt::format("Attribute \"Ri\" \"BasisStep\" takes 1 or 2 integers, found {}", s.size()));
      for (float v : s)
        if (v != std::floor(v) || std::fabs(v) > kMaxBasisStep)
          throw RibError(
              fmt::format("Attribute \"Ri\" \"BasisStep\" must be integers up to {}, found {}", kMaxBasisStep, v));
      ustep = int(s.front());
      vstep = int(s.back());
    }
    basis(uv[0], ustep, uv[1], vstep, loc);
  }
  for (const Param& p : params.params) {
    if (p.name == "Basis" || p.name == "BasisStep") continue;
    diag_.warning_once("attribute:Ri:" + p.name, loc, "Attribute",
                       "Attribute \"Ri\" \"" + p.name + "\" has no effect in darc: ignored");
  }
}

}  // namespace darc
