// A piecewise-constant distribution over [0, 1)^2, W x H cells of given weights (pbrt's
// Distribution2D: a marginal over rows, a conditional over each row's cells): sampling picks a row,
// then a cell in it, then a point uniformly inside the cell, with density proportional to the
// cell's weight. What an environment map's importance sampling needs (lookdev.md §2.3).
#pragma once

#include <cstddef>
#include <vector>

namespace darc {

class Distribution2D {
 public:
  Distribution2D() = default;
  // `weights` row by row (row 0 first), width x height of them, none negative. All zero (or
  // none): every cell equally likely.
  Distribution2D(const std::vector<float>& weights, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  struct Sample {
    float x = 0, y = 0;  // in [0, 1)^2; row y * height, cell x * width
    float pdf = 0;       // density with respect to area in [0, 1)^2
  };
  // The point (u0, u1) in [0, 1)^2 maps to: u1 picks the row, u0 the cell in it, and what is left
  // of each places the point inside its cell (so strata of (u0, u1) stay strata of the result).
  Sample sample(float u0, float u1) const;
  // The density at (x, y) in [0, 1)^2.
  float pdf(float x, float y) const;

 private:
  // Index of the interval of `cdf` (size n + 1, cdf[0] = 0, cdf[n] = 1) holding u, and where u
  // lies in it, in [0, 1).
  static size_t find(const float* cdf, size_t n, float u, float& within);

  int width_ = 0, height_ = 0;
  std::vector<float> row_cdf_;    // height + 1
  std::vector<float> cell_cdf_;   // height x (width + 1)
  std::vector<float> cell_pdf_;   // height x width, density of each cell
};

}  // namespace darc
