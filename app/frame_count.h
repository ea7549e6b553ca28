// How many frames a run will render, for progress ("frame 3 of 50" and a whole-run estimate):
// the FrameBegin requests of the input files found by a plain scan of their text (as many as
// --frames selects). It is an estimate: a FrameBegin in a comment or a string counts, one in an
// archive or a gzip file does not; a file without FrameBegin counts one frame per WorldBegin.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/frame_list.h"

namespace darc {

// The frames of `text` that `selected` (all when absent) selects.
int count_frames_in_text(std::string_view text, const std::optional<FrameList>& selected);

// Over the input files ("-", .gz files and anything but a regular file are not scanned, nor a
// file of more than `max_bytes` (0: no limit): nullopt, the count is unknown).
std::optional<int> count_frames(const std::vector<std::string>& inputs, const std::optional<FrameList>& selected,
                                std::uint64_t max_bytes = 0);

}  // namespace darc
