// What the speed-against-error benchmark measures, and the files it writes from it: the CSV
// (one row per scene, hider and sample count) and the Markdown report docs/performance.md.
#pragma once

#include <cstdio>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "bench/equal_error.h"
#include "bench/image_error.h"

namespace darc::bench {

// One render setting of one scene, measured.
struct Measurement {
  std::string scene;
  std::string hider;         // "distance" or "stochastic"
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

struct SceneReport {
  std::string name;
  int xres = 0, yres = 0;
  size_t curve_segments = 0;
  WidthStats widths;
  double reference_seconds = 0;  // 0 when it came from the cache
  std::vector<Measurement> settings;           // ordered: distance by samples, then stochastic by samples
  std::vector<VariantMeasurement> coverage;    // distance 1x1, one per coverage model
  std::vector<VariantMeasurement> sort_interval;  // distance 1x1, empty when not measured
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
