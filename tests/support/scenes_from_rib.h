// Scenes built from RIB text by SceneBuilder, in process: every frame with everything the builder
// reports (for the scene builder tests), or the one frame of a RIB ready to render (for the
// integrator and render tests).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/builder/scene_builder.h"

namespace darc::test {

// What building a RIB text gave: the finished scenes with the errors attributed to each, the
// failed frame numbers, and every diagnostic shown.
struct Built {
  std::vector<Scene> scenes;
  std::vector<FrameErrors> frame_errors;  // one per scene: what its image would record
  std::vector<int> failed;
  std::vector<Diagnostic> diagnostics;
};

// Parses `rib` (named "test.rib" in diagnostics) and builds every frame that `selected` accepts
// (all when it is empty), with `overrides` applied. Acceleration structures are not built.
Built build(const std::string& rib, std::function<bool(int)> selected = {}, FrameOverrides overrides = {});

// The one frame of `rib` (the last, if it has several) with its acceleration structure built.
// Every error diagnostic fails the calling test (non-fatally), and so does a RIB that gives no
// frame: build_frame then returns nothing, build_scene an empty Scene.
std::optional<Scene> build_frame(const std::string& rib);
Scene build_scene(const std::string& rib);

}  // namespace darc::test
