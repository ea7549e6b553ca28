// Counts over an image read back from a file, of the pixels whose colour passes a test: how many
// in all, and how many separate runs of them cross one row (separate strands or blades).
#pragma once

#include <functional>

#include "support/image_files.h"

namespace darc::test {

// A test on a pixel's colour (its first three channels).
using PixelTest = std::function<bool(float r, float g, float b)>;

// How many pixels pass `on`.
int count_pixels(const Pixels& p, const PixelTest& on);

// The most separate runs of passing pixels along any one row.
int max_runs_along_rows(const Pixels& p, const PixelTest& on);

}  // namespace darc::test
