// Loading a benchmark scene: the RIB text parsed by darc's own SceneBuilder (the first frame),
// then its acceleration structure built, each step timed, with the resident memory before and
// after (bench/process_memory.h). Shared by speed_vs_error and embree_peer, so that both
// render exactly the same Scene.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/scene/scene.h"

namespace darc::bench {

// The whole file, or nullopt when it cannot be read.
std::optional<std::string> read_text(const std::string& path);

struct LoadedScene {
  Scene scene;
  double parse_seconds = 0;  // RIB text -> Scene (parser and SceneBuilder)
  double build_seconds = 0;  // Scene::build_acceleration (the BVH or the uniform grid)
  // Resident set size and C heap in use before parsing and after building (the text itself is
  // already in memory before), each read after trimming the heap (bench/process_memory.h).
  uint64_t resident_before_bytes = 0, resident_after_bytes = 0;
  uint64_t heap_before_bytes = 0, heap_after_bytes = 0;
};

// Parses `text` (named `name` in diagnostics, which go to stderr) and returns its frame number
// `frame` (1: the first the file renders) with the acceleration structure of kind `accelerator`
// built (unless `build_acceleration` is false), or nullopt when it has errors or fewer frames.
std::optional<LoadedScene> load_scene(const std::string& text, const std::string& name, bool build_acceleration = true,
                                      AcceleratorKind accelerator = kDefaultAccelerator, int frame = 1);

}  // namespace darc::bench
