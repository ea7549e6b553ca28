#include "bench/scene_loading.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "bench/process_memory.h"
#include "core/scene/builder/scene_builder.h"
#include "parser/rib_parser.h"

namespace darc::bench {

std::optional<std::string> read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::optional<LoadedScene> load_scene(const std::string& text, const std::string& name, bool build_acceleration,
                                      AcceleratorKind accelerator, int frame) {
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  LoadedScene loaded;
  trim_heap();
  loaded.resident_before_bytes = resident_bytes();
  loaded.heap_before_bytes = heap_in_use_bytes();
  Clock::time_point t0 = Clock::now();
  std::optional<Scene> scene;
  {  // the parser and builder are gone before the resident set is read again
    Diagnostics diag;  // prints to stderr
    SceneBuilder::Callbacks cb;
    int frames_seen = 0;
    cb.frame_ready = [&](Scene&& s) {
      if (++frames_seen == frame) scene.emplace(std::move(s));
    };
    SceneBuilder builder(diag, cb);
    RibParser parser(builder, diag);
    parser.parse_string(text, name);
    builder.finish(SourceLoc{});
    if (diag.error_count() > 0 || !scene) return std::nullopt;
  }
  loaded.parse_seconds = seconds_since(t0);
  loaded.scene = std::move(*scene);
  if (build_acceleration) {
    Clock::time_point t1 = Clock::now();
    loaded.scene.build_acceleration(accelerator);
    loaded.build_seconds = seconds_since(t1);
  }
  trim_heap();
  loaded.resident_after_bytes = resident_bytes();
  loaded.heap_after_bytes = heap_in_use_bytes();
  return loaded;
}

}  // namespace darc::bench
