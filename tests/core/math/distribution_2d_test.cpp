#include "core/math/distribution_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace darc {
namespace {

// 4 x 3 cells with zeros, a heavy cell and a row of nothing.
const std::vector<float> kWeights = {1, 0, 2, 1,  //
                                     0, 0, 0, 0,  //
                                     8, 1, 0, 3};
constexpr int kW = 4, kH = 3;

double total_weight() {
  double s = 0;
  for (float w : kWeights) s += w;
  return s;
}

TEST(Distribution2D, CellDensityIsItsShareOfTheWeightTimesTheCellCount) {
  const Distribution2D d(kWeights, kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float expected = float(kWeights[size_t(y * kW + x)] / total_weight() * kW * kH);
      EXPECT_NEAR(d.pdf((x + 0.5f) / kW, (y + 0.5f) / kH), expected, 1e-5f) << x << "," << y;
    }
}

TEST(Distribution2D, SamplesFallInCellsAsOftenAsTheirWeightAndCarryTheirDensity) {
  const Distribution2D d(kWeights, kW, kH);
  constexpr int n = 400;  // a 400 x 400 grid of (u0, u1)
  std::vector<int> hits(kWeights.size(), 0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto s = d.sample((i + 0.5f) / n, (j + 0.5f) / n);
      ASSERT_GE(s.x, 0.0f);
      ASSERT_LT(s.x, 1.0f);
      ASSERT_GE(s.y, 0.0f);
      ASSERT_LT(s.y, 1.0f);
      ASSERT_GT(s.pdf, 0.0f) << "a sample in a cell of no weight";
      EXPECT_FLOAT_EQ(s.pdf, d.pdf(s.x, s.y));
      ++hits[size_t(int(s.y * kH) * kW + int(s.x * kW))];
    }
  for (size_t c = 0; c < kWeights.size(); ++c)
    EXPECT_NEAR(hits[c] / double(n * n), kWeights[c] / total_weight(), 0.003) << "cell " << c;
}

TEST(Distribution2D, SamplesAreUniformInsideTheirCell) {
  // One cell of all the weight: the samples cover it as (u0, u1) cover the square.
  const Distribution2D d({0, 0, 0, 5}, 2, 2);
  const auto lo = d.sample(0.0f, 0.0f), mid = d.sample(0.5f, 0.5f), hi = d.sample(0.999f, 0.999f);
  EXPECT_NEAR(lo.x, 0.5f, 1e-5f);
  EXPECT_NEAR(lo.y, 0.5f, 1e-5f);
  EXPECT_NEAR(mid.x, 0.75f, 1e-5f);
  EXPECT_NEAR(mid.y, 0.75f, 1e-5f);
  EXPECT_NEAR(hi.x, 0.9995f, 1e-4f);
  EXPECT_FLOAT_EQ(mid.pdf, 4.0f);
}

TEST(Distribution2D, NoWeightAtAllIsUniform) {
  const Distribution2D d(std::vector<float>(6, 0.0f), 3, 2);
  const auto s = d.sample(0.7f, 0.2f);
  EXPECT_FLOAT_EQ(s.pdf, 1.0f);
  EXPECT_NEAR(s.x, 0.7f, 1e-5f);
  EXPECT_NEAR(s.y, 0.2f, 1e-5f);
}

}  // namespace
}  // namespace darc
