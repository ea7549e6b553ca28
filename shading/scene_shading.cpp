#include "shading/scene_shading.h"

#include "shading/geometry_light.h"

namespace darc {

SceneShading::SceneShading(const Scene& scene, Diagnostics& diag)
    : textures_(std::make_unique<Textures>()), lights_(make_lights(scene.lights, diag)) {
  // AreaLightSource lights take their shape from the scene's geometry.
  for (uint32_t i = 0; i < scene.lights.size() && i < lights_.size(); ++i)
    if (scene.lights[i].geometry) lights_[i] = make_geometry_light(scene, i, diag);
  surfaces_.reserve(scene.materials.size());
  light_lists_.reserve(scene.materials.size());
  for (const Material& m : scene.materials) {
    if (!m.emissive_area_light.empty())
      surfaces_.push_back(make_area_light_surface(m.area_light_params));
    else
      surfaces_.push_back(make_surface_shader(m.surface, m.surface_params, m.surface_loc, diag, textures_.get()));
    LightList list;
    for (uint32_t i : m.lights)
      if (i < lights_.size()) list.push_back(lights_[i].get());
    light_lists_.push_back(std::move(list));
  }
}

}  // namespace darc
