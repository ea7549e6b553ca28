// The RI graphics state kept by SceneBuilder: options (frame-scoped) and attributes
// (AttributeBegin/End-scoped), following RI Spec 3.2 §4 and §5.
#pragma once

#include "core/scene/camera.h"
#include "core/math/curve_basis.h"
#include "core/math/matrix.h"
#include "core/scene/scene.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace darc {

// A light declared before WorldBegin (real files do this: Aqsis Misc/anim.rib). Its
// transform is relative to camera space, so it becomes a world light at each WorldBegin.
struct PendingLight {
  LightDesc desc;  // shader_to_world here holds shader-to-camera
  std::string handle;
};

struct Options {
  OutputSettings output;
  Camera::Projection projection = Camera::Projection::Orthographic;
  double fov_degrees = 90;
  std::optional<ScreenWindow> screen_window;  // explicit ScreenWindow
  std::optional<double> frame_aspect;          // explicit FrameAspectRatio
  double near_clip = 1e-10, far_clip = 1e38;
  double lens_radius = 0, focal_distance = 1;  // DepthOfField: a pinhole by default
  SourceLoc crop_loc;  // of the CropWindow in effect (its error is reported at WorldBegin)
  std::vector<PendingLight> pre_world_lights;
  // Camera requests: each name and the transform then in effect (world to that camera).
  std::vector<std::pair<std::string, Matrix4>> named_cameras;
  std::vector<std::string> texture_search_path;  // absolute folders (texture_paths.h)
};

struct Attributes {
  Vec3f color{1, 1, 1};
  Vec3f opacity{1, 1, 1};
  std::string surface = "defaultsurface";
  // Shared, never changed once set: AttributeBegin copies a pointer, not the list, and every
  // primitive made in one attribute state refers to the same list.
  std::shared_ptr<const ParamList> surface_params = std::make_shared<const ParamList>();
  SourceLoc surface_loc;
  int sides = 2;
  bool orientation_lh = true;  // RI default "outside" in the (left-handed) camera space
  CurveBasis ubasis = standard_basis("bezier").value();
  CurveBasis vbasis = standard_basis("bezier").value();
  bool matte = false;
  std::vector<uint32_t> lights_on;  // scene light indices
  std::string area_light;
  std::shared_ptr<const ParamList> area_light_params = std::make_shared<const ParamList>();
  int area_light_index = -1;  // the Scene::lights index of the AreaLightSource above
  // Attribute "light" "shadows" (BMRT, Aqsis): lights declared while it is "on" cast ray-traced
  // shadows, as if they had a "shadowname".
  bool light_shadows = false;
  // How the primitives block the light of shadow rays (Attribute "visibility" "transmission",
  // BMRT's Attribute "render" "casts_shadows").
  Transmission transmission = Transmission::Os;
};

}  // namespace darc
