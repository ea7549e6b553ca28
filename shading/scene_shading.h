// The shaders and lights of one scene, made once per frame from the scene's RIB names and
// parameters, and looked up by material index while rendering (read-only, thread-safe).
#pragma once

#include "core/scene/scene.h"
#include "parser/diagnostics.h"
#include "shading/lights.h"
#include "shading/surface_shader.h"

#include <memory>
#include <vector>

namespace darc {

class SceneShading {
 public:
  SceneShading(const Scene& scene, Diagnostics& diag);

  const SurfaceShader& surface(uint32_t material) const { return *surfaces_[material]; }
  const LightList& lights(uint32_t material) const { return light_lists_[material]; }

 private:
  // Before the shaders, which refer to it: they are destroyed first.
  std::unique_ptr<Textures> textures_;
  std::vector<std::unique_ptr<Light>> lights_;
  std::vector<std::unique_ptr<SurfaceShader>> surfaces_;
  std::vector<LightList> light_lists_;
};

}  // namespace darc
