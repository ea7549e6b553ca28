// The numeric parameters of the standard shaders darc implements (RI Spec 3.2 Appendix A, BMRT's
// mirror and glass, darc's hair; the RI lights and PRMan's shadow* variants), checked where
// Surface, LightSource and AreaLightSource are handled, as docs/parameters.md decides: a value of
// the wrong type or count is an error (the request is skipped), a value out of range is clamped
// with a warning that says the value used. The shaders themselves (shading/) read the checked
// list. Parameters of other shaders are the shaders' own business and pass unchecked.
#pragma once

#include <numbers>
#include <string>

#include "core/math/matrix.h"
#include "parser/diagnostics.h"
#include "parser/param_list.h"

namespace darc {

// The smallest roughness the specular lobes use: their exponent 1/roughness is capped at 10^4
// (a highlight a hundredth of a degree wide). A roughness <= 0 is clamped to it with a warning.
inline constexpr float kMinRoughness = 1e-4f;
// RI spotlight.sl's defaults, in radians: a 30-degree cone whose edge softens over 5 degrees.
inline constexpr float kDefaultSpotConeAngle = float(30 * std::numbers::pi / 180);
inline constexpr float kDefaultSpotConeDeltaAngle = float(5 * std::numbers::pi / 180);

// `params` of `shader` given to `request` ("Surface", "LightSource" or "AreaLightSource"), with
// the values out of range clamped (one warning at `loc` each). Throws RibError, naming the
// parameter, for a standard numeric parameter that is a string or has the wrong count.
ParamList checked_shader_parameters(const std::string& request, const std::string& shader, ParamList params,
                                    Diagnostics& diag, const SourceLoc& loc);

// Throws RibError when a light's "from" or "to" (their RI defaults (0 0 0) and (0 0 1) when
// absent) lies beyond the float range once placed by `shader_to_world`: the light could only
// send inf and NaN.
void check_light_positions(const ParamList& params, const Matrix4& shader_to_world);

}  // namespace darc
