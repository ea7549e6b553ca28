// The error of a rendered image against a reference, as the speed-against-error report states
// it: RMSE and maximum absolute difference over the R, G, B and A channels of the float images
// as rendered (premultiplied alpha, no display transform, no quantization).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "integrator/film.h"

namespace darc::bench {

struct ImageError {
  double rmse = 0;       // sqrt of the mean squared difference over every pixel and channel
  double max_error = 0;  // largest absolute difference of any channel of any pixel
  int pixels = 0;        // pixels compared
};

// Compares `image` with `reference` over the full display window (pixels outside a data window
// count as 0, as Image::at defines). Returns nullopt when the resolutions differ, when either
// lacks one of R, G, B, A, or when the window is empty. Non-finite values count as an error of
// 1 (a fully wrong channel), so the result is never NaN.
inline std::optional<ImageError> compare_rgba(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height) return std::nullopt;
  if (image.width <= 0 || image.height <= 0) return std::nullopt;
  static constexpr std::array<const char*, 4> kChannels{"R", "G", "B", "A"};
  std::array<int, 4> ci{}, cr{};
  for (size_t c = 0; c < kChannels.size(); ++c) {
    ci[c] = image.channel_index(kChannels[c]);
    cr[c] = reference.channel_index(kChannels[c]);
    if (ci[c] < 0 || cr[c] < 0) return std::nullopt;
  }
  constexpr double kNonFiniteError = 1.0;
  double sum_squared = 0, max_error = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      for (size_t c = 0; c < kChannels.size(); ++c) {
        double d = std::abs(double(image.at(x, y, ci[c])) - double(reference.at(x, y, cr[c])));
        if (!std::isfinite(d)) d = kNonFiniteError;
        sum_squared += d * d;
        max_error = std::max(max_error, d);
      }
    }
  }
  int pixels = image.width * image.height;
  return ImageError{std::sqrt(sum_squared / (double(pixels) * double(kChannels.size()))), max_error, pixels};
}

}  // namespace darc::bench
