#include "core/math/distribution_2d.h"

#include <algorithm>

namespace darc {

namespace {

// Fills cdf[0..n] (cdf[0] = 0, cdf[n] = 1) from n non-negative weights and returns their sum;
// uniform when they sum to zero. Sums in double so that a 2048-wide row of tiny and huge values
// still ends at exactly 1.
double build_cdf(const float* w, size_t n, float* cdf) {
  double sum = 0;
  for (size_t i = 0; i < n; ++i) sum += std::max(0.0f, w[i]);
  double run = 0;
  cdf[0] = 0;
  for (size_t i = 0; i < n; ++i) {
    run += sum > 0 ? double(std::max(0.0f, w[i])) : 1.0;
    cdf[i + 1] = float(run / (sum > 0 ? sum : double(n)));
  }
  cdf[n] = 1;
  return sum;
}

}  // namespace

Distribution2D::Distribution2D(const std::vector<float>& weights, int width, int height)
    : width_(std::max(width, 1)), height_(std::max(height, 1)) {
  const size_t w = size_t(width_), h = size_t(height_);
  std::vector<float> padded(w * h, 0.0f);
  if (width > 0 && height > 0 && weights.size() >= w * h) std::copy_n(weights.begin(), w * h, padded.begin());
  cell_cdf_.resize(h * (w + 1));
  cell_pdf_.resize(h * w);
  std::vector<float> row_sum(h);
  double total = 0;
  for (size_t y = 0; y < h; ++y) {
    row_sum[y] = float(build_cdf(&padded[y * w], w, &cell_cdf_[y * (w + 1)]));
    total += row_sum[y];
  }
  row_cdf_.resize(h + 1);
  build_cdf(row_sum.data(), h, row_cdf_.data());
  // Density of a cell over [0, 1)^2: its share of the total times the number of cells.
  for (size_t y = 0; y < h; ++y)
    for (size_t x = 0; x < w; ++x) {
      const double share = total > 0 ? double(std::max(0.0f, padded[y * w + x])) / total : 1.0 / double(w * h);
      cell_pdf_[y * w + x] = float(share * double(w * h));
    }
}

size_t Distribution2D::find(const float* cdf, size_t n, float u, float& within) {
  // The last i with cdf[i] <= u, among intervals of non-zero width.
  const size_t i = std::min(n - 1, size_t(std::upper_bound(cdf, cdf + n + 1, u) - cdf) - 1);
  size_t k = i;
  while (k + 1 < n && !(cdf[k + 1] > cdf[k])) ++k;  // u on a zero-width interval's edge: the next
  while (k > 0 && !(cdf[k + 1] > cdf[k])) --k;      // ... or the previous with width
  const float span = cdf[k + 1] - cdf[k];
  within = span > 0 ? std::clamp((u - cdf[k]) / span, 0.0f, 0x1.fffffep-1f) : 0.5f;
  return k;
}

Distribution2D::Sample Distribution2D::sample(float u0, float u1) const {
  Sample s;
  if (row_cdf_.empty()) return s;
  const size_t w = size_t(width_), h = size_t(height_);
  float in_row = 0, in_cell = 0;
  const size_t y = find(row_cdf_.data(), h, u1, in_row);
  const size_t x = find(&cell_cdf_[y * (w + 1)], w, u0, in_cell);
  s.x = std::min((float(x) + in_cell) / float(w), 0x1.fffffep-1f);
  s.y = std::min((float(y) + in_row) / float(h), 0x1.fffffep-1f);
  s.pdf = cell_pdf_[y * w + x];
  return s;
}

float Distribution2D::pdf(float x, float y) const {
  if (cell_pdf_.empty()) return 0;
  const int cx = std::clamp(int(x * float(width_)), 0, width_ - 1);
  const int cy = std::clamp(int(y * float(height_)), 0, height_ - 1);
  return cell_pdf_[size_t(cy) * size_t(width_) + size_t(cx)];
}

}  // namespace darc
