#include "support/image_compare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace darc::test {

std::vector<int> channel_indices(const Image& image, const Channels& channels) {
  std::vector<int> indices;
  if (channels.names.empty()) {
    for (int c = 0; c < image.channels(); ++c) indices.push_back(c);
  } else {
    for (const std::string& name : channels.names) indices.push_back(image.channel_index(name));
  }
  return indices;
}

ImageDifference compare(const Image& a, const Image& b, const Channels& channels) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height || !(a.data_window == b.data_window)) {
    ADD_FAILURE() << "images of different sizes: " << a.width << "x" << a.height << " and " << b.width << "x"
                  << b.height;
    return d;
  }
  const std::vector<int> ca = channel_indices(a, channels), cb = channel_indices(b, channels);
  if (ca.size() != cb.size() || std::count(ca.begin(), ca.end(), -1) || std::count(cb.begin(), cb.end(), -1)) {
    ADD_FAILURE() << "a compared channel is missing from an image";
    return d;
  }
  // Row-major over the data window (where the pixels are defined), channels in the order chosen.
  const size_t pixels = size_t(a.data_window.width()) * size_t(a.data_window.height());
  const size_t na = size_t(a.channels()), nb = size_t(b.channels());
  if (a.pixels.size() != pixels * na || b.pixels.size() != pixels * nb) {
    ADD_FAILURE() << "an image holds fewer or more values than its data window and channels";
    return d;
  }
  double sum_squares = 0, sum_abs = 0;
  for (size_t p = 0; p < pixels; ++p)
    for (size_t k = 0; k < ca.size(); ++k) {
      const double e = std::abs(double(a.pixels[p * na + size_t(ca[k])]) - double(b.pixels[p * nb + size_t(cb[k])]));
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

}  // namespace darc::test
