// Two images of the same size compared pixel by pixel over chosen channels: the root mean square,
// the largest and the mean absolute difference (as OIIO's ImageBufAlgo::compare gives them).
// Rendered in process (Image) or read back from the files darc wrote (Pixels).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "integrator/film.h"
#include "support/image_files.h"

namespace darc::test {

// The channels a comparison or a measure reads, by name; no names: every channel of the image.
struct Channels {
  std::vector<std::string> names;
};
inline const Channels kAllChannels{};
inline const Channels kRgb{{"R", "G", "B"}};
inline const Channels kRgba{{"R", "G", "B", "A"}};
inline const Channels kAlpha{{"A"}};

// The differences a - b over every pixel and every chosen channel.
struct ImageDifference {
  double rmse = 0;      // root mean square
  double max = 0;       // largest absolute difference
  double mean_abs = 0;  // mean absolute difference
  size_t values = 0;    // how many values were compared
};

// `a` against `b` over `channels`. Images of different sizes, or a chosen channel missing from
// either, fail the calling test (non-fatally) and compare as no values at all.
ImageDifference compare(const Image& a, const Image& b, const Channels& channels = kAllChannels);

// `a` against `b` over every channel (files read back carry no channel names here). Images of
// different sizes or channel counts fail the calling test (non-fatally) and compare as no values.
ImageDifference compare(const Pixels& a, const Pixels& b);

// The index of each chosen channel in `image` (-1 where it has no such channel).
std::vector<int> channel_indices(const Image& image, const Channels& channels);

}  // namespace darc::test
