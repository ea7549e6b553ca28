#include "support/pixel_measures.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace darc::test {

float channel_at(const Image& image, int x, int y, const char* name) {
  return image.at(x, y, image.channel_index(name));
}

double channel_sum(const Image& image, const Channels& channels) {
  const std::vector<int> indices = channel_indices(image, channels);
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c : indices) sum += image.at(x, y, c);
  return sum;
}

double channel_mean(const Image& image, const Channels& channels) {
  const size_t values = size_t(image.width) * size_t(image.height) * channel_indices(image, channels).size();
  return channel_sum(image, channels) / double(std::max<size_t>(1, values));
}

bool all_within(const Image& image, const Channels& channels, float lo, float hi) {
  const std::vector<int> indices = channel_indices(image, channels);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c : indices) {
        const float v = image.at(x, y, c);
        if (!std::isfinite(v) || v < lo || v > hi) return false;
      }
  return true;
}

}  // namespace darc::test
