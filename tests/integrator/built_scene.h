// The one frame of a RIB string with its acceleration structure built, for the integrator tests
// (a parse or build error fails the calling test).
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "core/scene/builder/scene_builder.h"
#include "parser/rib_parser.h"

namespace darc::test {

inline Scene build_scene(const std::string& rib) {
  Diagnostics diag([](const Diagnostic& d) {
    if (d.severity == Severity::Error) ADD_FAILURE() << d.str();
  });
  std::optional<Scene> scene;
  SceneBuilder::Callbacks callbacks;
  callbacks.frame_ready = [&](Scene&& s) { scene.emplace(std::move(s)); };
  SceneBuilder builder(diag, callbacks);
  RibParser parser(builder, diag);
  parser.parse_string(rib, "test.rib");
  builder.finish(SourceLoc{});
  if (!scene) {
    ADD_FAILURE() << "no frame";
    return Scene{};
  }
  scene->build_acceleration();
  return std::move(*scene);
}

}  // namespace darc::test
