#include "bench/timed_render.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "parser/diagnostics.h"

namespace darc::bench {

TimedImage render_timed(Scene& scene, const RenderOptions& options, int samples_per_axis, int max_runs,
                        double budget_seconds) {
  using Clock = std::chrono::steady_clock;
  scene.output.pixel_samples[0] = scene.output.pixel_samples[1] = samples_per_axis;
  TimedImage best;
  double total = 0;
  while (best.runs < std::max(1, max_runs) && (best.runs == 0 || total < budget_seconds)) {
    Diagnostics diag([](const Diagnostic&) {});
    FrameStats stats;
    Clock::time_point t0 = Clock::now();
    Image image = render_frame(scene, options, diag, stats);
    double t = std::chrono::duration<double>(Clock::now() - t0).count();
    total += t;
    if (best.runs == 0 || t < best.seconds) best.seconds = t;
    if (best.runs == 0) {
      best.image = std::move(image);
      best.counters = stats.counters;
    }
    ++best.runs;
  }
  return best;
}

}  // namespace darc::bench
