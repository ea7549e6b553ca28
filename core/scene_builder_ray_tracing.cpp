// SceneBuilder's RIB conventions for ray tracing: which lights cast ray-traced shadows (a
// "shadowname" light parameter, BMRT's Attribute "light" "shadows"). A spelling that asks for
// something darc does not have (a shadow map) gets the nearest thing it has, with one warning.
#include <fmt/format.h>

#include "core/scene_builder.h"

namespace darc {

namespace {

// The "shadowname" that asks for ray-traced shadows by name (BMRT, Aqsis, PRMan); any other
// non-empty name is a shadow map file.
constexpr const char* kRayTracedShadowName = "raytrace";

// The value of a parameter that must be one string. A number where a name is expected is a typo,
// not a convention, so it is an error.
const std::string& string_value(const std::string& what, const Param& p) {
  if (!p.decl.is_string() || p.strings.size() != 1)
    throw RibError(fmt::format("{} must be one string, found {} values declared as \"{}\"", what,
                               p.decl.is_string() ? p.strings.size() : p.floats.size(), to_string(p.decl)));
  return p.strings.front();
}

}  // namespace

bool SceneBuilder::light_casts_shadows(const std::string& handle, const ParamList& params, const SourceLoc& loc) {
  const Param* p = params.find("shadowname");
  const std::string shadow_name = p ? string_value("\"shadowname\"", *p) : std::string();
  if (!shadow_name.empty() && shadow_name != kRayTracedShadowName)
    diag_.warning_once(
        "shadowmap", loc, "LightSource",
        fmt::format("shadow maps are not supported: light \"{}\" uses ray-traced shadows instead of \"{}\"", handle,
                    shadow_name));
  // An empty name is how exporters write "no shadows" for a shader that has the parameter.
  return !shadow_name.empty() || attributes_.light_shadows;
}

void SceneBuilder::ray_tracing_attribute(const std::string& category, const Param& param, const SourceLoc& loc) {
  const std::string what = fmt::format("Attribute \"{}\" \"{}\"", category, param.name);
  if (category == "light" && param.name == "shadows") {
    const std::string& value = string_value(what, param);
    if (value != "on" && value != "off")
      throw RibError(fmt::format("{} must be \"on\" or \"off\", found \"{}\"", what, value));
    attributes_.light_shadows = value == "on";
    return;
  }
  // The rest of these categories (BMRT's "light" "nsamples", PRMan's "visibility" "camera", ...):
  // one warning per parameter, since the category itself is partly supported.
  diag_.warning_once("attribute:" + category + ":" + param.name, loc, "Attribute",
                     what + " has no effect in darc: ignored");
}

}  // namespace darc
