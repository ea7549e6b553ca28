// The contribution-threshold sweep of the secondary-ray report (docs/performance-secondary.md):
// one scene rendered with one hider and sample count at each of a list of
// RenderOptions::contribution_threshold values, with the secondary rays traced and pruned per
// kind (RayCounters::traced_by_kind, pruned_by_kind), and the error of each image against the
// same hider's image at threshold 0 (what the pruning alone changes) and against the reference.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "bench/image_error.h"
#include "core/scene/scene.h"
#include "integrator/film.h"
#include "integrator/render_frame.h"
#include "integrator/render_stats.h"

namespace darc::bench {

// The thresholds the report measures: 0 (every secondary ray traced, the baseline of the
// others), then a decade apart around the renderer's default (kDefaultContributionThreshold).
inline constexpr std::array<float, 5> kSweptContributionThresholds{0.0f, 1e-4f, 1e-3f, 1e-2f, 1e-1f};

struct ThresholdMeasurement {
  float threshold = 0;
  double seconds = 0;  // render_frame, the minimum over `runs` runs
  int runs = 0;
  uint64_t primary_rays = 0;
  std::array<uint64_t, kSecondaryKinds> traced{};  // by SecondaryKind
  std::array<uint64_t, kSecondaryKinds> pruned{};  // by SecondaryKind
  ImageError vs_unpruned;                          // against the image at threshold 0 (same hider, samples and seed)
  ImageError vs_reference;                         // against the scene's reference
};

struct ContributionSweep {
  std::string hider;                       // "distance" or "stochastic"
  int samples_per_axis = 1;                // N of the N x N samples per pixel
  std::vector<ThresholdMeasurement> rows;  // in the order of the thresholds given
};

// How each setting of a sweep is timed (bench/timed_render.h), and who hears of each row.
struct SweepSettings {
  int max_runs = 1;
  double budget_seconds = 0;
  std::function<void(const ThresholdMeasurement&)> on_measured;  // may be empty
};

// Renders `scene` with `options` (hider, threads, seed; its contribution_threshold is replaced)
// at N x N samples, first at threshold 0 for the unpruned image, then at each of `thresholds`
// (a threshold of 0 reuses that first render), and compares every image with the unpruned one
// and with `reference`. Nothing is printed.
ContributionSweep measure_contribution_sweep(Scene& scene, const RenderOptions& options, int samples_per_axis,
                                             std::span<const float> thresholds, const Image& reference,
                                             const SweepSettings& settings);

}  // namespace darc::bench
