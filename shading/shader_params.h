// Reading a shader's colour parameters: the first three numbers of a colour (or point) parameter,
// which the scene builder has already checked (core/scene/builder/shader_parameter_checks.h).
#pragma once

#include "core/math/vec.h"
#include "parser/param_list.h"

namespace darc {

// The colour `name` of `p`, or `fallback` when it is absent or has fewer than three numbers.
inline Vec3f param_color(const ParamList& p, const char* name, Vec3f fallback) {
  const Param* x = p.find(name);
  if (!x || x->decl.is_string() || x->floats.size() < 3) return fallback;
  return {x->floats[0], x->floats[1], x->floats[2]};
}

}  // namespace darc
