// RenderMan 21+ Bxdf requests mapped to darc's surface shaders (shading/surface_shader.h), with
// their main parameters: PxrSurface and PxrDisney -> plastic, PxrDiffuse -> matte, PxrConstant
// -> constant, PxrMarschnerHair -> chianghair; any other Bxdf -> defaultsurface. A Bxdf's colour
// (diffuse, base or emission colour) becomes Cs, as a Color request would make it. Parameters
// darc has no use for are listed in one warning per distinct request; README has the table.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/scene/ris/ris_patterns.h"
#include "core/math/vec.h"
#include "parser/diagnostics.h"
#include "parser/param_list.h"

namespace darc {

struct RisSurface {
  std::string shader;                // a darc surface shader name
  ParamList params;                  // its parameters (Ka, Kd, Ks, roughness, specularcolor)
  std::optional<Vec3f> color;        // Cs, when the Bxdf gives one
  std::vector<std::string> dropped;  // the request's parameters that darc does not use
};

// Pure: no warnings (SceneBuilder gives them from `dropped` and `unevaluated`).
struct RisSurfaceMapping {
  RisSurface surface;
  bool known = true;  // false: not a Bxdf darc maps (defaultsurface)
  // Parameters connected to a pattern darc cannot evaluate (they keep their default), with why.
  std::vector<std::string> unevaluated;
};
RisSurfaceMapping map_ris_bxdf(const std::string& name, const ParamList& params, const RisPatterns& patterns);

// The warnings of one Bxdf request, once per distinct text (Diagnostics::warning_once).
void warn_ris_bxdf(const std::string& name, const RisSurfaceMapping& m, Diagnostics& diag, const SourceLoc& loc);

}  // namespace darc
