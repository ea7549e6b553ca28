#include "support/image_compare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace darc::test {
namespace {

// One image's values as the comparison reads them: `pixels` pixels of `stride` interleaved
// channels each, of which those at `chosen` are compared, in that order.
struct ComparedValues {
  std::span<const float> values;
  size_t stride = 0;
  std::vector<int> chosen;
};

ImageDifference compare_values(const ComparedValues& a, const ComparedValues& b, size_t pixels) {
  ImageDifference d;
  if (a.values.size() != pixels * a.stride || b.values.size() != pixels * b.stride) {
    ADD_FAILURE() << "an image holds fewer or more values than its size and channels";
    return d;
  }
  double sum_squares = 0, sum_abs = 0;
  for (size_t p = 0; p < pixels; ++p)
    for (size_t k = 0; k < a.chosen.size(); ++k) {
      const double e = std::abs(double(a.values[p * a.stride + size_t(a.chosen[k])]) -
                                double(b.values[p * b.stride + size_t(b.chosen[k])]));
      sum_squares += e * e;
      sum_abs += e;
      d.max = std::max(d.max, e);
      ++d.values;
    }
  if (d.values > 0) {
    d.rmse = std::sqrt(sum_squares / double(d.values));
    d.mean_abs = sum_abs / double(d.values);
  }
  return d;
}

std::vector<int> every_channel(int channels) {
  std::vector<int> indices;
  for (int c = 0; c < channels; ++c) indices.push_back(c);
  return indices;
}

}  // namespace

std::vector<int> channel_indices(const Image& image, const Channels& channels) {
  if (channels.names.empty()) return every_channel(image.channels());
  std::vector<int> indices;
  for (const std::string& name : channels.names) indices.push_back(image.channel_index(name));
  return indices;
}

ImageDifference compare(const Image& a, const Image& b, const Channels& channels) {
  if (a.width != b.width || a.height != b.height || !(a.data_window == b.data_window)) {
    ADD_FAILURE() << "images of different sizes: " << a.width << "x" << a.height << " and " << b.width << "x"
                  << b.height;
    return {};
  }
  const std::vector<int> ca = channel_indices(a, channels), cb = channel_indices(b, channels);
  if (ca.size() != cb.size() || std::count(ca.begin(), ca.end(), -1) || std::count(cb.begin(), cb.end(), -1)) {
    ADD_FAILURE() << "a compared channel is missing from an image";
    return {};
  }
  // Row-major over the data window (where the pixels are defined), channels in the order chosen.
  const size_t pixels = size_t(a.data_window.width()) * size_t(a.data_window.height());
  return compare_values({a.pixels, size_t(a.channels()), ca}, {b.pixels, size_t(b.channels()), cb}, pixels);
}

ImageDifference compare(const Pixels& a, const Pixels& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
    ADD_FAILURE() << "images of different sizes or channels: " << a.width << "x" << a.height << "x" << a.channels
                  << " and " << b.width << "x" << b.height << "x" << b.channels;
    return {};
  }
  const std::vector<int> all = every_channel(a.channels);
  const size_t pixels = size_t(a.width) * size_t(a.height);
  return compare_values({a.v, size_t(a.channels), all}, {b.v, size_t(b.channels), all}, pixels);
}

}  // namespace darc::test
