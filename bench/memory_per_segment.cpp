// Memory per curve segment on a 1M-segment hair scene (docs/memory.md): the RIB text, the
// parse (SceneBuilder's CurveSet), and each acceleration structure (the BVH darc renders with,
// and the uniform grid), as the C heap's growth (glibc's exact count) and the resident set's
// peak during each step (VmHWM reset before it where the kernel allows). The figures are what
// SceneBuilder's memory limit (core/scene/frame_memory.h) estimates a frame from.
//
//   memory_per_segment [--segments N] [--text-out FILE]
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <random>
#include <string>

#include "bench/process_memory.h"
#include "core/scene/frame_memory.h"
#include "core/scene/builder/scene_builder.h"
#include "parser/rib_parser.h"

namespace {

using namespace darc;
using namespace darc::bench;

// A ball of hair: strands of 10 cubic Bézier segments (31 vertices), varying width, one
// Curves request per 1000 strands, as exporters write them.
std::string hair_rib(int64_t segments) {
  constexpr int kSegmentsPerStrand = 10, kStrandsPerRequest = 1000;
  const int64_t strands = (segments + kSegmentsPerStrand - 1) / kSegmentsPerStrand;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::string rib =
      "Format 640 480 1\nProjection \"perspective\" \"fov\" 30\nTranslate 0 0 6\nWorldBegin\n"
      "Basis \"bezier\" 3 \"bezier\" 3\nSurface \"hair\"\n";
  char buf[96];
  for (int64_t first = 0; first < strands; first += kStrandsPerRequest) {
    const int64_t n = std::min<int64_t>(kStrandsPerRequest, strands - first);
    rib += "Curves \"cubic\" [";
    for (int64_t i = 0; i < n; ++i) rib += " 31";
    rib += "] \"nonperiodic\" \"P\" [";
    for (int64_t i = 0; i < n; ++i) {
      double x = u(rng), y = u(rng), z = u(rng);
      const double dx = 0.02 * u(rng), dy = 0.02 * u(rng), dz = 0.02 * u(rng);
      for (int v = 0; v < 31; ++v) {
        std::snprintf(buf, sizeof buf, " %.4f %.4f %.4f", x, y, z);
        rib += buf;
        x += dx + 0.003 * u(rng);
        y += dy + 0.003 * u(rng);
        z += dz + 0.003 * u(rng);
      }
    }
    rib += "] \"width\" [";
    for (int64_t i = 0; i < n; ++i) rib += " 0.004 0.0036 0.0032 0.0028 0.0024 0.002 0.0016 0.0012 0.0008 0.0004 0.0001";
    rib += "]\n";
  }
  rib += "WorldEnd\n";
  return rib;
}

double mb(uint64_t b) { return double(b) / (1024.0 * 1024.0); }
double per(uint64_t b, size_t n) { return n ? double(b) / double(n) : 0.0; }
uint64_t growth(uint64_t after, uint64_t before) { return after > before ? after - before : 0; }

}  // namespace

int main(int argc, char** argv) {
  int64_t segments = 1'000'000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--segments") && i + 1 < argc) segments = std::atoll(argv[++i]);
    else {
      std::fprintf(stderr, "usage: memory_per_segment [--segments N]\n");
      return 2;
    }
  }
  const bool peak_resets = reset_peak_resident();
  trim_heap();
  const uint64_t rss0 = resident_bytes(), heap0 = heap_in_use_bytes();

  std::string text = hair_rib(segments);
  const uint64_t heap_text = heap_in_use_bytes();

  // Parse: the CurveSet, and the peak while the parser holds a request's parameter arrays.
  trim_heap();
  reset_peak_resident();
  const uint64_t rss_before_parse = resident_bytes();
  std::optional<Scene> scene;
  {
    Diagnostics diag;
    SceneBuilder::Callbacks cb;
    cb.frame_ready = [&](Scene&& s) { scene.emplace(std::move(s)); };
    SceneBuilder builder(diag, cb);
    RibParser parser(builder, diag);
    parser.parse_string(text, "hair.rib");
    builder.finish(SourceLoc{});
    if (diag.error_count() > 0 || !scene) return 1;
  }
  const uint64_t parse_peak = growth(peak_resident_bytes(), rss_before_parse);
  trim_heap();
  const uint64_t heap_scene = heap_in_use_bytes();
  const size_t n = scene->curves.size();
  const uint64_t curve_bytes = scene->curves.memory_bytes();

  struct Built {
    const char* name;
    uint64_t own_bytes, heap_growth, peak_growth;
  };
  auto build = [&](AcceleratorKind kind, const char* name) {
    Scene copy = *scene;  // each structure over the same curves, from the same state
    trim_heap();
    const uint64_t heap_before = heap_in_use_bytes();
    reset_peak_resident();
    const uint64_t rss_before = resident_bytes();
    copy.build_acceleration(kind);
    const uint64_t peak = growth(peak_resident_bytes(), rss_before);
    trim_heap();
    return Built{name, copy.accel.memory_bytes(), growth(heap_in_use_bytes(), heap_before), peak};
  };
  const Built bvh = build(AcceleratorKind::Bvh, "BVH (4-wide, the default)");
  const Built grid = build(AcceleratorKind::Grid, "uniform grid");

  std::printf("segments: %zu (%" PRId64 " asked), RIB text %.1f MB (%.0f B/segment)%s\n\n", n, segments,
              mb(text.size()), per(text.size(), n), peak_resets ? "" : " [VmHWM reset refused: peaks count from start]");
  std::printf("| step | heap growth MB | heap B/segment | own count B/segment | peak resident growth MB | peak B/segment |\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::printf("| RIB text held in memory | %.1f | %.0f | - | - | - |\n", mb(growth(heap_text, heap0)),
              per(growth(heap_text, heap0), n));
  std::printf("| parse + build curves (CurveSet) | %.1f | %.0f | %.0f | %.1f | %.0f |\n", mb(growth(heap_scene, heap_text)),
              per(growth(heap_scene, heap_text), n), per(curve_bytes, n), mb(parse_peak), per(parse_peak, n));
  for (const Built& b : {bvh, grid})
    std::printf("| %s | %.1f | %.0f | %.0f | %.1f | %.0f |\n", b.name, mb(b.heap_growth), per(b.heap_growth, n),
                per(b.own_bytes, n), mb(b.peak_growth), per(b.peak_growth, n));
  const double estimate = double(frame_memory_estimate(n, 0, 0));
  std::printf("\nSceneBuilder's estimate of the frame (core/scene/frame_memory.h): %.1f MB, %.0f B/segment; "
              "measured CurveSet + BVH after the build %.0f B/segment, peak during the BVH build %.0f B/segment "
              "over the CurveSet\n",
              mb(uint64_t(estimate)), estimate / double(n), per(curve_bytes + bvh.own_bytes, n),
              per(curve_bytes, n) + per(bvh.peak_growth, n));
  std::printf("process resident at start %.1f MB\n", mb(rss0));
  return 0;
}
