// Frame selections for --frames: "1-10,15,20-40x5" (ranges inclusive, optional step).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace darc {

class FrameList {
 public:
  // Returns nullopt (and sets error) on a malformed list.
  static std::optional<FrameList> parse(const std::string& text, std::string& error);
  bool contains(int frame) const;

 private:
  struct Range {
    int first, last, step;
  };
  std::vector<Range> ranges_;
};

// Substitutes the frame number into an output name: a run of '#' becomes the zero-padded
// number of that width, and a printf-style %d / %0Nd likewise. Names without a pattern are
// returned unchanged.
std::string substitute_frame_number(const std::string& name, int frame);

// True when substitute_frame_number would put the frame number into `name` (a '#' run, %d or
// %0Nd), so that each frame gets a file of its own.
bool has_frame_number_pattern(const std::string& name);

}  // namespace darc
