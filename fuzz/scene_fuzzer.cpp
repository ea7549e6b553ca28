// libFuzzer target for the RIB parser driving the real SceneBuilder: the input is parsed as a
// RIB file and every frame is built as darc would build it, without rendering. ReadArchive and
// the procedurals are refused (RibParser::allow_archive_files(false)), so no input reaches the
// file system or starts a program. Small finished scenes also get both acceleration structures
// built; large ones are skipped, so that an input's cost stays near linear in its size
// (libFuzzer's -rss_limit_mb and -malloc_limit_mb, given by scripts/fuzz, bound the memory an
// input may make the builder allocate).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/scene/scene.h"
#include "core/scene/builder/scene_builder.h"
#include "parser/diagnostics.h"
#include "parser/rib_parser.h"

namespace {

// Scenes with more primitives than this are not given acceleration structures: the builds are
// O(n log n) and would dominate an execution without reaching new code.
constexpr size_t kMaxPrimitivesToAccelerate = 4096;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  darc::Diagnostics diag{[](const darc::Diagnostic& d) { (void)d.str(); }};
  darc::SceneBuilder::Callbacks callbacks;
  callbacks.frame_ready = [](darc::Scene&& scene) {
    if (scene.primitive_count() > kMaxPrimitivesToAccelerate) return;
    scene.build_acceleration(darc::AcceleratorKind::Bvh);
    scene.build_acceleration(darc::AcceleratorKind::Grid);
  };
  darc::SceneBuilder builder(diag, callbacks);
  darc::RibParser parser(builder, diag);
  parser.allow_archive_files(false);
  parser.parse_string(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.rib");
  builder.finish(darc::SourceLoc{});
  return 0;
}
