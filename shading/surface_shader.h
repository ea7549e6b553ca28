// Surface shaders by RIB name: the RI standard surfaces (RI Spec 3.2 Appendix A) with their
// default parameters, evaluated with the lights that illuminate the primitive.
#pragma once

#include "parser/diagnostics.h"
#include "parser/param_list.h"
#include "shading/lights.h"
#include "shading/shading_point.h"

#include <memory>
#include <string>
#include <vector>

namespace darc {

struct ShadeResult {
  Vec3f Ci;  // premultiplied by Oi, as RI shaders output
  Vec3f Oi;
};

// The lights a primitive sees (pointers into the scene's light list).
using LightList = std::vector<const Light*>;

class SurfaceShader {
 public:
  virtual ~SurfaceShader() = default;
  virtual ShadeResult shade(const ShadingPoint& sp, const LightList& lights) const = 0;
};

// Makes the shader for a RIB Surface call. Unknown names get one warning each and
// "defaultsurface" (documented in README). Known names: constant, matte, plastic, metal,
// shinymetal (= metal: no environment maps), paintedplastic (= plastic: no textures),
// hair (Kajiya-Kay, PRMan application note 19 parameters), defaultsurface.
std::unique_ptr<SurfaceShader> make_surface_shader(const std::string& name, const ParamList& params,
                                                   const SourceLoc& loc, Diagnostics& diag);

// An emissive surface for geometry inside an AreaLightSource block: Ci = intensity * lightcolor.
std::unique_ptr<SurfaceShader> make_area_light_surface(const ParamList& light_params);

}  // namespace darc
