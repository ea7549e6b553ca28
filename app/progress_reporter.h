// Progress on stderr: one line updated in place on a terminal, otherwise one line per 10 %.
// In a sequence each line also says which frame of how many it is and estimates the whole run
// from the time the frames so far took.
#pragma once

#include <chrono>
#include <string>

namespace darc {

class ProgressReporter {
 public:
  ProgressReporter(bool enabled, bool is_terminal) : enabled_(enabled), terminal_(is_terminal) {}
  // The frames the run will render (0: unknown; app/frame_count.h).
  void set_frames_in_run(int frames) { frames_in_run_ = frames; }
  // A frame of the run that is not rendered (its image exists): the run has one fewer.
  void skip_frame() { frames_in_run_ = frames_in_run_ > 0 ? frames_in_run_ - 1 : 0; }
  void start(const std::string& label);
  void update(double fraction);  // fraction of the frame done, in [0, 1]
  void finish();

 private:
  bool enabled_, terminal_;
  std::string label_;
  int last_step_ = -1;         // last 10 % step logged (non-terminal output)
  double best_fraction_ = -1;  // largest fraction reported so far this frame
  std::chrono::steady_clock::time_point start_;
  int frames_in_run_ = 0;
  int frames_started_ = 0;
  std::chrono::steady_clock::time_point run_start_;
  // "frame 3/50, " when the run has more than one frame; the run's remaining time after the frame's.
  std::string frame_prefix() const;
  std::string run_estimate(double fraction) const;
};

}  // namespace darc
