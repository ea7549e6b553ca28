#include "app/progress_reporter.h"

#include <cstdio>

namespace darc {

namespace {
// Non-terminal output prints one line per this many percent.
constexpr int kLogStepPercent = 10;
}  // namespace

void ProgressReporter::start(const std::string& label) {
  label_ = label;
  last_step_ = -1;
  best_fraction_ = -1;
  start_ = std::chrono::steady_clock::now();
}

void ProgressReporter::update(double fraction) {
  if (!enabled_) return;
  // Tiles finish on several threads, and a thread may report its (smaller) count after another
  // thread reported a larger one; progress only moves forward, so stale reports are dropped
  // (otherwise the log would step back and forth across a 10 % boundary).
  if (!(fraction > best_fraction_)) return;  // also drops NaN
  best_fraction_ = fraction;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  int percent = int(fraction * 100.0 + 1e-9);
  double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  if (terminal_) {
    std::fprintf(stderr, "\r%s: %3d%% (%.1fs, ETA %.1fs)   ", label_.c_str(), percent, elapsed, eta);
    std::fflush(stderr);
    return;
  }
  int step = percent / kLogStepPercent;
  if (step <= last_step_) return;
  last_step_ = step;
  std::fprintf(stderr, "%s: %d%% (%.1fs elapsed, ETA %.1fs)\n", label_.c_str(), step * kLogStepPercent, elapsed, eta);
}

void ProgressReporter::finish() {
  if (enabled_ && terminal_) std::fprintf(stderr, "\n");
}

}  // namespace darc
