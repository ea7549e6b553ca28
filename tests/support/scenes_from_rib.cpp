#include "support/scenes_from_rib.h"

#include <gtest/gtest.h>

#include <utility>

#include "parser/rib_parser.h"

namespace darc::test {

Built build(const std::string& rib, std::function<bool(int)> selected, FrameOverrides overrides) {
  Built out;
  Diagnostics diag([&](const Diagnostic& d) { out.diagnostics.push_back(d); });
  SceneBuilder::Callbacks cb;
  cb.frame_selected = std::move(selected);
  cb.frame_ready = [&](Scene&& s) {
    out.scenes.push_back(std::move(s));
    out.frame_errors.push_back(diag.frame_errors());
  };
  cb.frame_failed = [&](int f) { out.failed.push_back(f); };
  SceneBuilder builder(diag, cb, overrides);
  RibParser parser(builder, diag);
  parser.parse_string(rib, "test.rib");
  builder.finish(SourceLoc{});
  return out;
}

std::optional<Scene> build_frame(const std::string& rib) {
  Built built = build(rib);
  int errors = 0;
  for (const Diagnostic& d : built.diagnostics)
    if (d.severity == Severity::Error) {
      ++errors;
      ADD_FAILURE() << d.str();
    }
  if (built.scenes.empty()) {
    ADD_FAILURE() << "the RIB gave no frame (" << errors << " errors)";
    return std::nullopt;
  }
  Scene scene = std::move(built.scenes.back());
  scene.build_acceleration();
  return scene;
}

Scene build_scene(const std::string& rib) {
  std::optional<Scene> scene = build_frame(rib);
  return scene ? std::move(*scene) : Scene{};
}

}  // namespace darc::test
