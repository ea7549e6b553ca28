// Measures of one image: a channel's value at a pixel, sums and means of channels, whether every
// value is finite or within a range.
#pragma once

#include <limits>

#include "integrator/film.h"
#include "support/image_compare.h"

namespace darc::test {

// The value of the channel called `name` at pixel (x, y); 0 where the image has no such channel.
float channel_at(const Image& image, int x, int y, const char* name);
inline float alpha_at(const Image& image, int x, int y) { return channel_at(image, x, y, "A"); }

// The sum and the mean of the chosen channels' values over every pixel.
double channel_sum(const Image& image, const Channels& channels = kAllChannels);
double channel_mean(const Image& image, const Channels& channels = kAllChannels);

// Every value of the chosen channels finite and in [lo, hi].
bool all_within(const Image& image, const Channels& channels, float lo, float hi);
inline bool all_finite(const Image& image, const Channels& channels = kAllChannels) {
  return all_within(image, channels, -std::numeric_limits<float>::max(), std::numeric_limits<float>::max());
}

}  // namespace darc::test
