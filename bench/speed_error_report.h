// What the speed-against-error benchmark measures, and the files it writes from it: the CSV
// (one row per scene, hider and sample count) and the Markdown report docs/performance.md.
#pragma once

#include <cstdint>
#include <cstdio>
#include <ostream>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "bench/contribution_sweep.h"
#include "bench/equal_error.h"
#include "bench/image_error.h"

namespace darc::bench {

// Work counted during one render of a setting (the first of its runs; renders are
// deterministic, so every run counts the same). From darc's FrameStats::counters, or for the
// Embree peer its rtcIntersect1 calls.
struct WorkCounters {
  uint64_t primary_rays = 0;
  uint64_t segment_tests = 0;   // ray-curve segment tests (darc)
  uint64_t fragments = 0;       // A-buffer fragments (distance hider)
  uint64_t cells_visited = 0;   // grid cells visited (darc)
  uint64_t intersect_calls = 0;  // rtcIntersect1 calls (Embree peer)
  uint64_t secondary_rays = 0;   // shadow, reflection and refraction rays traced (darc)
  uint64_t pruned_rays = 0;      // secondary rays not traced: contribution weight under the threshold (darc)
  uint64_t surface_tests = 0;    // ray-surface tests: exact rays and footprint sub-rays (darc)
  uint64_t surface_pieces = 0;   // surfaces a footprint covered analytically, without sub-rays (darc)
  uint64_t shadow_rays = 0;      // shadow rays traced (part of secondary_rays; darc)
  uint64_t shadow_segment_tests = 0;  // the segment tests of shadow rays (part of segment_tests; darc)
};

// One render setting of one scene, measured.
struct Measurement {
  std::string scene;
  std::string hider;         // "distance", "stochastic" or "embree"
  int samples_per_axis = 1;  // N of the N x N samples per pixel
  double seconds = 0;        // wall clock of render_frame, the minimum over `runs` runs
  int runs = 0;
  ImageError error;          // against the scene's reference
};

// A distance-hider variant at 1x1: a coverage model or an A-buffer sort interval.
struct VariantMeasurement {
  std::string label;  // "box", "disc", "square", or the sort interval "1".."10"
  double seconds = 0;
  int runs = 0;
  ImageError error;
};

// Strand widths in pixels over the visible ends of the curve segments.
struct WidthStats {
  size_t count = 0;
  double min = 0, p5 = 0, median = 0, p95 = 0, max = 0;
};

// Loading and building one scene, and the memory it took (bench/scene_loading.h).
struct SceneLoadCost {
  uint64_t rib_bytes = 0;
  double parse_seconds = 0;         // RIB text -> Scene
  double build_seconds = 0;         // darc's acceleration structure (RunDescription::accelerator)
  uint64_t accelerator_bytes = 0;   // its own count (Accelerator::memory_bytes)
  uint64_t curve_bytes = 0;         // the CurveSet's own count (CurveSet::memory_bytes)
  uint64_t resident_growth_bytes = 0;  // resident set after parse + build minus before
  uint64_t heap_growth_bytes = 0;      // C heap in use after parse + build minus before: the Scene
  uint64_t peak_resident_bytes = 0;    // VmHWM at the end of the scene's measurements (0: unknown)
  bool peak_is_per_scene = false;      // the peak was reset before the scene (else: since process start)
  // The Embree peer's scene (zero when not measured).
  double embree_build_seconds = 0;     // rtcCommitScene
  uint64_t embree_bytes = 0;           // Embree's own allocations (its memory monitor), peak
  uint64_t embree_resident_growth_bytes = 0;
};

struct SceneReport {
  std::string name;
  int xres = 0, yres = 0;
  size_t curve_segments = 0;
  WidthStats widths;
  double reference_seconds = 0;  // 0 when it came from the cache
  int reference_samples_per_axis = 0;  // 0: the run's (RunDescription::reference_samples_per_axis)
  SceneLoadCost load;
  std::vector<Measurement> settings;           // ordered: distance by samples, then stochastic, then embree
  // The work of settings[i] is work[i] (empty when not counted; kept apart from Measurement so
  // that its aggregate layout, which the CSV tests spell out, stays as it is).
  std::vector<WorkCounters> work;
  // The Embree peer's N x N image against darc's stochastic N x N image (the same rays): how
  // well the two agree, by N. Empty when the peer was not measured.
  std::vector<std::pair<int, ImageError>> embree_vs_stochastic;
  std::vector<VariantMeasurement> coverage;    // distance 1x1, one per coverage model
  std::vector<VariantMeasurement> sort_interval;  // distance 1x1, empty when not measured
  // The secondary-ray report's contribution-threshold sweeps, one per hider and sample count
  // (empty in the other reports).
  std::vector<ContributionSweep> contribution_sweeps;
};

// How a run was made, for the report's header.
struct RunDescription {
  std::string size;        // "small" or "large"
  std::string date;        // ISO 8601, UTC
  int cores = 0;           // std::thread::hardware_concurrency
  std::string cpu_model;   // from /proc/cpuinfo, may be empty
  int reference_samples_per_axis = 0;
  unsigned reference_seed = 0;
  int max_runs = 0;
  double repeat_budget_seconds = 0;
  int threads = 0;           // render threads actually used
  std::string embree;        // "Embree 3.13.5" when the peer was measured, else empty
  bool quick = false;        // the smoke run (reduced resolution and reference)
  std::string accelerator;   // darc's acceleration structure: "bvh" or "grid"
  float contribution_threshold = 0;            // of the measured renders (RenderOptions)
  float reference_contribution_threshold = 0;  // of the references
};

// The CSV's header, in column order.
inline constexpr const char* kCsvHeader = "scene,hider,samples,seconds,rmse,max_error";

// Writes the CSV: the header, then one row per measurement in the given order. `samples` is the
// number of samples per pixel (N*N); numbers are written with enough digits to read back.
inline void write_speed_error_csv(std::ostream& out, std::span<const Measurement> rows) {
  out << kCsvHeader << "\n";
  for (const Measurement& m : rows) {
    char buf[160];
    std::snprintf(buf, sizeof buf, ",%d,%.6g,%.6g,%.6g", m.samples_per_axis * m.samples_per_axis, m.seconds,
                  m.error.rmse, m.error.max_error);
    out << m.scene << "," << m.hider << buf << "\n";
  }
}

// The stochastic settings of `scene` as a curve ordered by cost, for equal_error_time.
inline std::vector<SpeedErrorPoint> stochastic_curve(const SceneReport& scene) {
  std::vector<SpeedErrorPoint> curve;
  for (const Measurement& m : scene.settings)
    if (m.hider == "stochastic") curve.push_back({m.seconds, m.error.rmse});
  return curve;
}

// Writes docs/performance.md: the run's description, a summary, a table per scene with the
// equal-error speed-ups, the coverage models and the sort intervals.
void write_performance_markdown(std::ostream& out, const RunDescription& run, std::span<const SceneReport> scenes);

}  // namespace darc::bench
