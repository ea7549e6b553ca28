// The pure arithmetic of the 640x480 speed-against-error report (docs/performance-640.md):
// work per ray, time per segment test, memory per segment, the equal-error speed-up against a
// chosen baseline hider (darc's stochastic hider or the Embree peer), and the CSV rows.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bench/equal_error.h"
#include "bench/speed_error_report.h"

namespace darc::bench {

// count / rays, 0 when no ray was counted (a setting without counters).
inline double per_ray(uint64_t count, uint64_t rays) { return rays > 0 ? double(count) / double(rays) : 0.0; }

// Nanoseconds of one thread per segment test: render seconds x threads / segment tests. An upper
// bound on the cost of a test (the whole render is charged to the tests); 0 without tests.
inline double ns_per_segment_test(double seconds, int threads, uint64_t segment_tests) {
  return segment_tests > 0 ? seconds * double(threads) * 1e9 / double(segment_tests) : 0.0;
}

// bytes / segments, 0 for a scene without segments.
inline double bytes_per_segment(uint64_t bytes, size_t segments) {
  return segments > 0 ? double(bytes) / double(segments) : 0.0;
}

// The (seconds, RMSE) curve of one hider of a scene, in the order measured (by sample count).
inline std::vector<SpeedErrorPoint> hider_curve(const SceneReport& scene, std::string_view hider) {
  std::vector<SpeedErrorPoint> curve;
  for (const Measurement& m : scene.settings)
    if (m.hider == hider) curve.push_back({m.seconds, m.error.rmse});
  return curve;
}

inline const Measurement* find_measurement(const SceneReport& scene, std::string_view hider, int samples_per_axis) {
  for (const Measurement& m : scene.settings)
    if (m.hider == hider && m.samples_per_axis == samples_per_axis) return &m;
  return nullptr;
}

// How long `baseline` needs to reach the RMSE of the distance hider at N x N, against the
// distance hider's own time.
struct EqualErrorSpeedup {
  EqualErrorTime baseline;  // the baseline's time at that error (or a bound, see its kind)
  double distance_seconds = 0;
  double ratio() const { return baseline.seconds / std::max(distance_seconds, kMinLogSeconds); }
  std::string text() const { return format_speedup(baseline, distance_seconds); }
};

// nullopt when the scene has no distance N x N setting or no setting of `baseline`.
inline std::optional<EqualErrorSpeedup> equal_error_speedup(const SceneReport& scene, int distance_samples_per_axis,
                                                            std::string_view baseline) {
  const Measurement* d = find_measurement(scene, "distance", distance_samples_per_axis);
  std::vector<SpeedErrorPoint> curve = hider_curve(scene, baseline);
  if (!d || curve.empty()) return std::nullopt;
  return EqualErrorSpeedup{equal_error_time(curve, d->error.rmse), d->seconds};
}

// The 640 CSV's header, in column order: the small/large CSV's columns, then the scene's
// reference sample count and the work per primary ray.
inline constexpr const char* kCsv640Header =
    "scene,hider,samples,seconds,rmse,max_error,reference_samples,segment_tests_per_ray,fragments_per_ray,"
    "cells_per_ray,intersect_calls_per_ray,ns_per_segment_test,surface_tests_per_ray,surface_pieces_per_ray,"
    "shadow_rays_per_ray,segment_tests_per_shadow_ray";

// Writes the header and one row per setting of every scene (`samples` = N*N, reference_samples
// likewise); `threads` is the render thread count (for ns_per_segment_test).
inline void write_speed_error_640_csv(std::ostream& out, std::span<const SceneReport> scenes, int threads,
                                      int run_reference_samples_per_axis) {
  out << kCsv640Header << "\n";
  for (const SceneReport& s : scenes) {
    const int ref = s.reference_samples_per_axis > 0 ? s.reference_samples_per_axis : run_reference_samples_per_axis;
    for (size_t i = 0; i < s.settings.size(); ++i) {
      const Measurement& m = s.settings[i];
      const WorkCounters w = i < s.work.size() ? s.work[i] : WorkCounters{};
      char buf[480];
      std::snprintf(buf, sizeof buf, ",%d,%.6g,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g",
                    m.samples_per_axis * m.samples_per_axis, m.seconds, m.error.rmse, m.error.max_error, ref * ref,
                    per_ray(w.segment_tests, w.primary_rays), per_ray(w.fragments, w.primary_rays),
                    per_ray(w.cells_visited, w.primary_rays), per_ray(w.intersect_calls, w.primary_rays),
                    ns_per_segment_test(m.seconds, threads, w.segment_tests), per_ray(w.surface_tests, w.primary_rays),
                    per_ray(w.surface_pieces, w.primary_rays), per_ray(w.shadow_rays, w.primary_rays),
                    per_ray(w.shadow_segment_tests, w.shadow_rays));
      out << m.scene << "," << m.hider << buf << "\n";
    }
  }
}

// Writes docs/performance-640.md: the run, a summary with the equal-error speed-ups of the
// distance hider against darc's stochastic hider and the Embree peer, a table per scene with
// the work per ray, and the loading and memory costs.
void write_performance_640_markdown(std::ostream& out, const RunDescription& run, std::span<const SceneReport> scenes);

}  // namespace darc::bench
