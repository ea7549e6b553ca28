// SceneBuilder's RenderMan 21+ (RIS) requests. Bxdf sets the surface shader as Surface does (and
// Cs, from the Bxdf's colour), Light declares a light as LightSource does (the same handles for
// Illuminate), Pattern keeps a node for the Bxdfs that reference it, Integrator is an option that
// darc records and reports (--stats) but does not follow. The mappings are core/ris_*_mapping.h.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "core/scene/ris/ris_bxdf_mapping.h"
#include "core/scene/ris/ris_light_mapping.h"
#include "core/scene/builder/scene_builder.h"
#include "core/scene/builder/shader_parameter_checks.h"

namespace darc {

void SceneBuilder::bxdf(const std::string& name, const std::string& handle, const ParamList& params,
                        const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.bxdf(name, handle, params, loc); })) return;
  const RisSurfaceMapping m = map_ris_bxdf(name, params, ris_patterns_);
  warn_ris_bxdf(name, m, diag_, loc);
  ParamList list = checked_shader_parameters("Surface", m.surface.shader, m.surface.params, diag_, loc);
  resolve_texture_names("Bxdf", m.surface.shader, list, "shades with the PxrTexture's missingColor", loc);
  auto checked = std::make_shared<const ParamList>(std::move(list));
  attributes_.surface = m.surface.shader;
  attributes_.surface_params = std::move(checked);
  attributes_.surface_loc = loc;
  if (m.surface.color) attributes_.color = *m.surface.color;
}

void SceneBuilder::light(const std::string& name, const std::string& handle, const ParamList& params,
                         const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.light(name, handle, params, loc); })) return;
  const RisLightMapping m = map_ris_light(name, params, ctm_);
  warn_ris_light(name, m, diag_, loc);
  if (m.shader.empty()) {
    // No light, but Illuminate may name it: its handle stays valid and switches nothing.
    light_handles_.erase(handle);
    area_light_handles_.insert(handle);
    return;
  }
  add_light(m.shader, handle, m.params, loc, m.casts_shadows, "Light");
  // RenderMan 21+ lights are scene objects, not attributes: exporters wrap each in its own
  // AttributeBegin/End (for its transform), and it lights everything after it unless Illuminate
  // switches it off. So it is on in every enclosing attribute state of the world block too.
  const auto it = light_handles_.find(handle);
  if (!in_world_ || it == light_handles_.end()) return;
  for (size_t i = world_attribute_depth_; i < saved_attributes_.size(); ++i) {
    std::vector<uint32_t>& on = saved_attributes_[i].lights_on;
    if (std::find(on.begin(), on.end(), it->second) == on.end()) on.push_back(it->second);
  }
}

void SceneBuilder::pattern(const std::string& name, const std::string& handle, const ParamList& params,
                           const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.pattern(name, handle, params, loc); })) return;
  if (name == "PxrHairColor") {
    std::vector<std::string> dropped;
    for (const Param& p : params.params)
      if (p.name != "melanin" && p.name != "melaninRedness") dropped.push_back(p.name);
    if (!dropped.empty()) {
      const std::string list = fmt::format("{}", fmt::join(dropped, ", "));
      diag_.warning_once("ris-pattern-dropped:" + name + ":" + list, loc, "Pattern",
                         fmt::format("{} is read for its melanin colour only: dropped {}", name, list));
    }
  }
  ris_patterns_[handle] = RisPattern{name, params};
}

void SceneBuilder::integrator(const std::string& name, const std::string&, const ParamList&, const SourceLoc& loc) {
  if (!option_allowed("Integrator", loc)) return;
  diag_.warning_once("ris-integrator:" + name, loc, "Integrator",
                     fmt::format("\"{}\" is recorded (--stats) but darc renders with its own integrator", name));
  options_.output.integrator = name;
}

}  // namespace darc
