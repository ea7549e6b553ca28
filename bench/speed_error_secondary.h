// The pure parts of the secondary-ray report (docs/performance-secondary.md, written by
// scripts/bench-speed-vs-error --secondary): the equal-error comparison of the 640 report on
// scenes with shadows, a mirror and glass, without the Embree peer (it traces camera rays only),
// and the contribution-threshold sweeps (bench/contribution_sweep.h), with their CSV.
#pragma once

#include <cstdio>
#include <ostream>
#include <span>

#include "bench/contribution_sweep.h"
#include "bench/speed_error_640.h"
#include "bench/speed_error_report.h"

namespace darc::bench {

// The sweep CSV's header, in column order: one row per scene, sweep and threshold; `samples` is
// N*N; traced_* and pruned_* are rays of that SecondaryKind.
inline constexpr const char* kCsvSweepHeader =
    "scene,hider,samples,threshold,seconds,runs,primary_rays,traced_shadow,traced_reflection,traced_refraction,"
    "pruned_shadow,pruned_reflection,pruned_refraction,rmse_vs_unpruned,max_vs_unpruned,rmse_vs_reference,"
    "max_vs_reference";

inline void write_contribution_sweep_csv(std::ostream& out, std::span<const SceneReport> scenes) {
  out << kCsvSweepHeader << "\n";
  for (const SceneReport& s : scenes) {
    for (const ContributionSweep& sweep : s.contribution_sweeps) {
      for (const ThresholdMeasurement& m : sweep.rows) {
        char buf[400];
        std::snprintf(buf, sizeof buf, ",%d,%.6g,%.6g,%d,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%.6g,%.6g,%.6g,%.6g",
                      sweep.samples_per_axis * sweep.samples_per_axis, double(m.threshold), m.seconds, m.runs,
                      (unsigned long long)m.primary_rays, (unsigned long long)m.traced[0],
                      (unsigned long long)m.traced[1], (unsigned long long)m.traced[2], (unsigned long long)m.pruned[0],
                      (unsigned long long)m.pruned[1], (unsigned long long)m.pruned[2], m.vs_unpruned.rmse,
                      m.vs_unpruned.max_error, m.vs_reference.rmse, m.vs_reference.max_error);
        out << s.name << "," << sweep.hider << buf << "\n";
      }
    }
  }
}

// The sweep's row at threshold 0 (every secondary ray traced), or nullptr.
inline const ThresholdMeasurement* unpruned_row(const ContributionSweep& sweep) {
  for (const ThresholdMeasurement& m : sweep.rows)
    if (m.threshold == 0) return &m;
  return nullptr;
}

// The time of `row` over the sweep's time at threshold 0: below 1 when pruning saved time; 0
// without a threshold-0 row or when it took no measurable time.
inline double time_vs_unpruned(const ContributionSweep& sweep, const ThresholdMeasurement& row) {
  const ThresholdMeasurement* base = unpruned_row(sweep);
  return base && base->seconds > 0 ? row.seconds / base->seconds : 0.0;
}

// Writes docs/performance-secondary.md: the run, a summary of the equal-error speed-ups of the
// distance hider against the stochastic hider, a table per scene with its secondary rays per
// camera ray, and a pruning table per scene and sweep.
void write_performance_secondary_markdown(std::ostream& out, const RunDescription& run,
                                          std::span<const SceneReport> scenes);

}  // namespace darc::bench
