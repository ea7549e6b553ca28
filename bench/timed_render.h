// One render setting timed for the speed-against-error report: render_frame run a few times on a
// noisy machine, the minimum time kept (the best estimate of the undisturbed time), the image and
// counters of the first run kept (renders are deterministic, so every run gives the same).
#pragma once

#include "core/scene/scene.h"
#include "integrator/film.h"
#include "integrator/render_frame.h"
#include "integrator/render_stats.h"

namespace darc::bench {

struct TimedImage {
  Image image;
  double seconds = 0;  // wall clock of render_frame, the minimum over the runs
  int runs = 0;
  RayCounters counters;  // of the first run
};

// Renders `scene` at `samples_per_axis` x `samples_per_axis` samples per pixel (it sets the
// scene's PixelSamples), at least once and then again while fewer than `max_runs` runs were
// made and they took less than `budget_seconds` in total. Only render_frame is timed;
// diagnostics are dropped (the parse reported them, and every run repeats the same).
TimedImage render_timed(Scene& scene, const RenderOptions& options, int samples_per_axis, int max_runs,
                        double budget_seconds);

}  // namespace darc::bench
