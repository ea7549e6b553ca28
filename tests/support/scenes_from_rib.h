// Builds the scenes of a RIB text with SceneBuilder and keeps everything it reports (the
// finished scenes with the errors attributed to each, the failed frame numbers, every shown
// diagnostic), shared by the scene builder tests.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/scene/builder/scene_builder.h"
#include "parser/rib_parser.h"

namespace darc::test {

struct Built {
  std::vector<Scene> scenes;
  std::vector<FrameErrors> frame_errors;  // one per scene: what its image would record
  std::vector<int> failed;
  std::vector<Diagnostic> diagnostics;
};

inline Built build(const std::string& rib, std::function<bool(int)> selected = {}, FrameOverrides overrides = {}) {
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

}  // namespace darc::test
