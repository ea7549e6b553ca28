// The lat-long map of the dome: RenderMan's orientation (lookdev.md §2.2), and importance sampling
// whose estimate L / pdf integrates the map exactly as the map's texels cover the sphere.
#include "shading/latlong_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace darc {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(LatLongMap, DomeSpaceAxesLandWhereRenderManPutsThem) {
  float s, t;
  LatLongMap::to_st({0, 0, 1}, s, t);
  EXPECT_NEAR(t, 0.0f, 1e-6f) << "+z is the top row";
  LatLongMap::to_st({0, 0, -1}, s, t);
  EXPECT_NEAR(t, 1.0f, 1e-6f) << "-z the bottom row";
  const struct {
    Vec3f d;
    float s;
  } axes[] = {{{1, 0, 0}, 0.0f}, {{0, -1, 0}, 0.25f}, {{-1, 0, 0}, 0.5f}, {{0, 1, 0}, 0.75f}};
  for (const auto& a : axes) {
    LatLongMap::to_st(a.d, s, t);
    EXPECT_NEAR(s, a.s, 1e-6f) << a.d.x << " " << a.d.y;
    EXPECT_NEAR(t, 0.5f, 1e-6f);
    const Vec3f back = LatLongMap::from_st(s, t);
    EXPECT_NEAR(length(back - a.d), 0.0f, 1e-6f);
  }
}

TEST(LatLongMap, ATexelIsSeenOverItsPartOfTheSphere) {
  // 4 x 2: the upper row red, green, blue, white from s = 0; the lower row black.
  std::vector<Vec3f> texels(8, Vec3f{});
  texels[0] = {1, 0, 0};
  texels[1] = {0, 1, 0};
  texels[2] = {0, 0, 1};
  texels[3] = {1, 1, 1};
  const LatLongMap map(texels, 4, 2);
  const float d = std::sqrt(0.5f);
  EXPECT_EQ(map.radiance(normalize(Vec3f{1, -0.2f, 0.5f})).x, 1.0f);  // s just above 0: red
  EXPECT_EQ(map.radiance(normalize(Vec3f{-d, -d, 0.3f})).y, 1.0f);   // s = 0.375: green
  EXPECT_EQ(map.radiance(normalize(Vec3f{-d, d, 0.3f})).z, 1.0f);    // s = 0.625: blue
  EXPECT_EQ(map.radiance(normalize(Vec3f{d, d, 0.3f})), (Vec3f{1, 1, 1}));
  EXPECT_EQ(map.radiance(normalize(Vec3f{1, 1, -0.3f})), (Vec3f{}));
}

// The exact integral of a piecewise-constant map over the sphere: texel (i, j) covers
// (2 pi / W) (cos theta_j - cos theta_j+1) steradians.
double integral(const std::vector<Vec3f>& texels, int w, int h) {
  double sum = 0;
  for (int j = 0; j < h; ++j) {
    const double solid = 2 * kPi / w * (std::cos(kPi * j / h) - std::cos(kPi * (j + 1) / h));
    for (int i = 0; i < w; ++i) sum += texels[size_t(j * w + i)].y * solid;
  }
  return sum;
}

TEST(LatLongMap, SamplesEstimateTheMapsIntegralAndCarryTheirDensity) {
  constexpr int w = 32, h = 16;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vec3f> texels(w * h);
  for (Vec3f& c : texels) {
    const float v = u(rng) < 0.1f ? 50.0f * u(rng) : u(rng) < 0.3f ? 0.0f : u(rng);  // a few bright texels, some black
    c = {v, v, v};
  }
  const LatLongMap map(texels, w, h);
  constexpr int n = 256;
  double estimate = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      LatLongMap::Sample s;
      if (!map.sample((a + 0.5f) / n, (b + 0.5f) / n, s)) continue;
      ASSERT_GT(s.radiance.y, 0.0f) << "a black texel was drawn";
      ASSERT_NEAR(length(s.direction), 1.0f, 1e-5f);
      EXPECT_NEAR(s.pdf, map.pdf(s.direction), 1e-3f * s.pdf);
      EXPECT_EQ(s.radiance, map.radiance(s.direction));
      estimate += s.radiance.y / s.pdf;
    }
  estimate /= double(n) * n;
  EXPECT_NEAR(estimate, integral(texels, w, h), 0.002 * integral(texels, w, h));
}

TEST(LatLongMap, AUniformMapIsSampledUniformlyOverTheSphere) {
  const LatLongMap map(std::vector<Vec3f>(16 * 8, Vec3f{1, 1, 1}), 16, 8);
  LatLongMap::Sample s;
  ASSERT_TRUE(map.sample(0.3f, 0.6f, s));
  // The rows' weights follow sin theta at their centres: close to, not exactly, 1 / (4 pi).
  EXPECT_NEAR(s.pdf, 1 / (4 * kPi), 0.03 / (4 * kPi));
  EXPECT_NEAR(map.pdf({0, 0, 1}), 0.0f, 1e-9f) << "the pole has no density";
}

}  // namespace
}  // namespace darc
