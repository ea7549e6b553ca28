// SceneBuilder's RIB conventions for ray tracing: which lights cast ray-traced shadows (a
// "shadowname" light parameter, BMRT's Attribute "light" "shadows"), what blocks their light
// (Attribute "visibility" "transmission", BMRT's Attribute "render" "casts_shadows") and how deep
// reflection and refraction go (Option "trace" "maxdepth"). A spelling that asks for something
// darc does not have (a shadow map, shader-computed opacity) gets the nearest thing it has, with
// one warning.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "core/scene/builder/scene_builder.h"

namespace darc {

namespace {

// The "shadowname" that asks for ray-traced shadows by name (BMRT, Aqsis, PRMan); any other
// non-empty name is a shadow map file.
constexpr const char* kRayTracedShadowName = "raytrace";

// The value of a parameter that must be one string. A number where a name is expected is a typo,
// not a convention, so it is an error.
const std::string& string_value(const std::string& what, const Param& p) {
  if (!p.decl.is_string())
    throw RibError(fmt::format("{} must be a string, found numbers declared as \"{}\"", what, to_string(p.decl)));
  if (p.strings.size() != 1) throw RibError(fmt::format("{} must be one string, found {}", what, p.strings.size()));
  return p.strings.front();
}

// A string value of a transmission attribute and what it means.
struct TransmissionSpelling {
  const char* value;
  Transmission transmission;
  bool asks_for_shader_opacity;  // darc does not run shaders for shadow rays: Os stands in
};

// Attribute "visibility" "string transmission" (PRMan before 11, Aqsis).
constexpr TransmissionSpelling kVisibilityTransmission[] = {
    {"opaque", Transmission::Opaque, false},
    {"transparent", Transmission::Transparent, false},
    {"Os", Transmission::Os, false},
    {"shader", Transmission::Os, true},
};

// Attribute "render" "string casts_shadows" (BMRT).
constexpr TransmissionSpelling kRenderCastsShadows[] = {
    {"none", Transmission::Transparent, false},
    {"opaque", Transmission::Opaque, false},
    {"Os", Transmission::Os, false},
    {"shade", Transmission::Os, true},
};

std::string accepted_values(std::span<const TransmissionSpelling> spellings) {
  std::string list;
  for (const TransmissionSpelling& s : spellings) list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", s.value);
  return list;
}

const TransmissionSpelling& spelling_of(const std::string& what, const Param& p,
                                        std::span<const TransmissionSpelling> spellings) {
  const std::string& value = string_value(what, p);
  for (const TransmissionSpelling& s : spellings)
    if (value == s.value) return s;
  throw RibError(fmt::format("{} must be one of {}, found \"{}\"", what, accepted_values(spellings), value));
}

// The deepest reflection and refraction chain Option "trace" "maxdepth" may ask for; deeper
// requests are clamped to it with a warning. Secondary rays recurse: two facing mirrors overflow
// the 8 MB main stack between 3000 and 10000 bounces (Release build), so 100 keeps a wide margin
// for a 4 MB TBB worker stack and a sanitizer build, while a chain that long contributes nothing
// visible (PRMan's default is 10; glass's internal reflections fall under the 1e-3 pruning
// threshold within a few bounces).
constexpr int kMaxTraceDepth = 100;

// Option "trace" "int maxdepth": any count of bounces from 0 (no reflection or refraction rays)
// to kMaxTraceDepth is valid; what it costs is the integrator's business.
int trace_max_depth(const Param& p) {
  const char* what = "Option \"trace\" \"maxdepth\"";
  if (p.decl.is_string() || p.floats.size() != 1) throw RibError(fmt::format("{} must be one integer", what));
  const double depth = p.floats[0];
  if (!(depth >= 0) || depth != std::floor(depth) || depth > std::numeric_limits<int>::max())
    throw RibError(fmt::format("{} must be an integer >= 0, found {}", what, p.floats[0]));
  return int(depth);
}

}  // namespace

void SceneBuilder::trace_option(const ParamList& params, const SourceLoc& loc) {
  if (!option_allowed("Option", loc)) return;
  for (const Param& p : params.params) {
    if (p.name == "maxdepth") {
      const int depth = trace_max_depth(p);
      if (depth > kMaxTraceDepth)
        diag_.warning(loc, "Option",
                      fmt::format("Option \"trace\" \"maxdepth\" {} is deeper than darc traces: clamped to {}", depth,
                                  kMaxTraceDepth));
      options_.output.trace_max_depth = std::min(depth, kMaxTraceDepth);
      continue;
    }
    diag_.warning_once("option:trace:" + p.name, loc, "Option",
                       "Option \"trace\" \"" + p.name + "\" has no effect in darc: ignored");
  }
}

void SceneBuilder::set_transmission(Transmission t, bool asks_for_shader_opacity, const SourceLoc& loc) {
  if (asks_for_shader_opacity)
    diag_.warning_once("transmission:shader", loc, "Attribute",
                       "shader-computed opacity is not run for shadows: Os is used");
  attributes_.transmission = t;
}

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
  if (category == "visibility" && param.name == "transmission") {
    if (param.decl.is_string()) {
      const TransmissionSpelling& s = spelling_of(what, param, kVisibilityTransmission);
      set_transmission(s.transmission, s.asks_for_shader_opacity, loc);
      return;
    }
    // "int transmission" (PRMan 11 on): seen by shadow rays or not; what they see blocks by Os.
    const bool zero_or_one = param.floats.size() == 1 && (param.floats[0] == 0 || param.floats[0] == 1);
    if (!zero_or_one)
      throw RibError(fmt::format("{} must be 0 or 1 (or one of {}), found {}", what,
                                 accepted_values(kVisibilityTransmission),
                                 param.floats.size() == 1 ? fmt::format("{}", param.floats[0])
                                                          : fmt::format("{} values", param.floats.size())));
    set_transmission(param.floats[0] == 1 ? Transmission::Os : Transmission::Transparent, false, loc);
    return;
  }
  if (category == "render" && param.name == "casts_shadows") {
    const TransmissionSpelling& s = spelling_of(what, param, kRenderCastsShadows);
    set_transmission(s.transmission, s.asks_for_shader_opacity, loc);
    return;
  }
  // The rest of these categories (BMRT's "light" "nsamples", PRMan's "visibility" "camera", ...):
  // one warning per parameter, since the category itself is partly supported.
  diag_.warning_once("attribute:" + category + ":" + param.name, loc, "Attribute",
                     what + " has no effect in darc: ignored");
}

}  // namespace darc
