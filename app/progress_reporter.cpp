#include "app/progress_reporter.h"

#include <cstdio>

namespace darc {

namespace {
// Non-terminal output prints one line per this many percent.
constexpr int kLogStepPercent = 10;
}  // namespace

std::string ProgressReporter::frame_prefix() const {
  if (frames_in_run_ <= 1) return "";
  char buf[48];
  std::snprintf(buf, sizeof buf, "frame %d/%d ", frames_started_, frames_in_run_);
  return buf;
}

std::string ProgressReporter::run_estimate(double fraction) const {
  if (frames_in_run_ <= 1 || frames_started_ > frames_in_run_) return "";
  // The frames so far, this one's done fraction included, at the pace they went.
  const double done = double(frames_started_ - 1) + fraction;
  if (!(done > 0)) return "";
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start_).count();
  const double remaining = elapsed / done * (double(frames_in_run_) - done);
  char buf[64];
  if (remaining >= 3600) std::snprintf(buf, sizeof buf, "; run ETA %dh%02dm", int(remaining / 3600), int(remaining / 60) % 60);
  else if (remaining >= 60) std::snprintf(buf, sizeof buf, "; run ETA %dm%02ds", int(remaining / 60), int(remaining) % 60);
  else std::snprintf(buf, sizeof buf, "; run ETA %.0fs", remaining);
  return buf;
}

void ProgressReporter::start(const std::string& label) {
  if (frames_started_++ == 0) run_start_ = std::chrono::steady_clock::now();
  label_ = frame_prefix() + label;
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
    std::fprintf(stderr, "\r%s: %3d%% (%.1fs, ETA %.1fs%s)   ", label_.c_str(), percent, elapsed, eta,
                 run_estimate(fraction).c_str());
    std::fflush(stderr);
    return;
  }
  int step = percent / kLogStepPercent;
  if (step <= last_step_) return;
  last_step_ = step;
  std::fprintf(stderr, "%s: %d%% (%.1fs elapsed, ETA %.1fs%s)\n", label_.c_str(), step * kLogStepPercent, elapsed, eta,
               run_estimate(fraction).c_str());
}

void ProgressReporter::finish() {
  if (enabled_ && terminal_) std::fprintf(stderr, "\n");
}

}  // namespace darc
