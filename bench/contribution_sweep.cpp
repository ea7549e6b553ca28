#include "bench/contribution_sweep.h"

#include <optional>

#include "bench/timed_render.h"

namespace darc::bench {

namespace {

ImageError error_between(const Image& image, const Image& other) {
  std::optional<ImageError> e = compare_rgba(image, other);
  return e ? *e : ImageError{1.0, 1.0, 0};  // images of one scene always compare; never NaN
}

ThresholdMeasurement measurement_of(float threshold, const TimedImage& t, const Image& unpruned,
                                    const Image& reference) {
  ThresholdMeasurement m;
  m.threshold = threshold;
  m.seconds = t.seconds;
  m.runs = t.runs;
  m.primary_rays = t.counters.primary_rays;
  for (int k = 0; k < kSecondaryKinds; ++k) {
    m.traced[size_t(k)] = t.counters.traced_by_kind[k];
    m.pruned[size_t(k)] = t.counters.pruned_by_kind[k];
  }
  m.vs_unpruned = error_between(t.image, unpruned);
  m.vs_reference = error_between(t.image, reference);
  return m;
}

}  // namespace

ContributionSweep measure_contribution_sweep(Scene& scene, const RenderOptions& options, int samples_per_axis,
                                             std::span<const float> thresholds, const Image& reference,
                                             const SweepSettings& settings) {
  ContributionSweep sweep;
  sweep.hider = to_string(options.hider);
  sweep.samples_per_axis = samples_per_axis;
  RenderOptions ro = options;
  ro.contribution_threshold = 0;
  const TimedImage unpruned = render_timed(scene, ro, samples_per_axis, settings.max_runs, settings.budget_seconds);
  for (float threshold : thresholds) {
    ThresholdMeasurement m;
    if (threshold == 0) {
      m = measurement_of(threshold, unpruned, unpruned.image, reference);
    } else {
      ro.contribution_threshold = threshold;
      TimedImage t = render_timed(scene, ro, samples_per_axis, settings.max_runs, settings.budget_seconds);
      m = measurement_of(threshold, t, unpruned.image, reference);
    }
    if (settings.on_measured) settings.on_measured(m);
    sweep.rows.push_back(m);
  }
  return sweep;
}

}  // namespace darc::bench
