// RenderMan 21+ Light requests mapped to darc's light shaders (shading/lights.h). A RIS light's
// colour is intensity * 2^exposure * lightColor. PxrDistantLight -> distantlight along the
// light's +z axis (the side RenderMan's Pxr lights emit to: ../shared/docs/lookdev.md §2.2),
// its angleExtent as distantlight's "angle" (sampled over that cone: soft shadows).
// PxrRectLight, PxrDiskLight and PxrSphereLight -> darc's area lights rectlight, disklight and
// spherelight (the same unit shapes, emitting toward +z where flat; shading/area_lights.h),
// sampled with soft shadows; their shapes are not drawn. PxrDomeLight -> domelight (radiance from
// every direction, its lightColorMap as "mapname": shading/dome_light.h). README has the table.
#pragma once

#include <string>
#include <vector>

#include "core/math/matrix.h"
#include "parser/diagnostics.h"
#include "parser/param_list.h"

namespace darc {

// PxrDistantLight's default angleExtent (degrees): the sun's angular diameter, as RenderMan's.
inline constexpr float kDefaultSunAngleDegrees = 0.53f;

struct RisLightMapping {
  std::string shader;                // a darc light shader; empty: no light (an unknown RIS light)
  ParamList params;                  // intensity, lightcolor, from, to (in the light's space), cone parameters
  bool casts_shadows = true;         // enableShadows (RenderMan's default: on)
  std::vector<std::string> dropped;  // the request's parameters darc does not use
  std::string approximation;         // how the light was approximated, for the warning; or empty
};

// `light_to_world` places the light (its scale sets an area light's size, hence its power).
RisLightMapping map_ris_light(const std::string& name, const ParamList& params, const Matrix4& light_to_world);

// The warnings of one Light request, once per distinct text (Diagnostics::warning_once).
void warn_ris_light(const std::string& name, const RisLightMapping& m, Diagnostics& diag, const SourceLoc& loc);

}  // namespace darc
