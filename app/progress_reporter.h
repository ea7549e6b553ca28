// Progress on stderr: one line updated in place on a terminal, otherwise one line per 10 %.
#pragma once

#include <chrono>
#include <string>

namespace darc {

class ProgressReporter {
 public:
  ProgressReporter(bool enabled, bool is_terminal) : enabled_(enabled), terminal_(is_terminal) {}
  void start(const std::string& label);
  void update(double fraction);  // fraction of the frame done, in [0, 1]
  void finish();

 private:
  bool enabled_, terminal_;
  std::string label_;
  int last_step_ = -1;         // last 10 % step logged (non-terminal output)
  double best_fraction_ = -1;  // largest fraction reported so far this frame
  std::chrono::steady_clock::time_point start_;
};

}  // namespace darc
