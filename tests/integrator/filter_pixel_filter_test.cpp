#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "integrator/pixel_filter.h"

namespace darc {
namespace {

PixelFilter filter(const char* name, float xw, float yw) {
  auto f = make_pixel_filter(name, xw, yw);
  EXPECT_TRUE(f.has_value()) << name;
  return f.value_or(PixelFilter{});
}

TEST(PixelFilter, DefaultIsGaussianTwoByTwo) {
  const PixelFilter f = default_pixel_filter();
  EXPECT_EQ(f.type, PixelFilter::Type::Gaussian);
  EXPECT_EQ(f.xwidth, 2.0f);
  EXPECT_EQ(f.ywidth, 2.0f);
}

TEST(PixelFilter, RibNamesAndUnknownName) {
  EXPECT_EQ(filter("box", 1, 1).type, PixelFilter::Type::Box);
  EXPECT_EQ(filter("triangle", 2, 2).type, PixelFilter::Type::Triangle);
  EXPECT_EQ(filter("gaussian", 2, 2).type, PixelFilter::Type::Gaussian);
  EXPECT_EQ(filter("catmull-rom", 4, 4).type, PixelFilter::Type::CatmullRom);
  EXPECT_EQ(filter("sinc", 4, 4).type, PixelFilter::Type::Sinc);
  EXPECT_FALSE(make_pixel_filter("mitchell", 2, 2).has_value());
  EXPECT_FALSE(make_pixel_filter("", 2, 2).has_value());
}

TEST(PixelFilter, BadWidthsAreSanitised) {
  const PixelFilter f = filter("box", std::numeric_limits<float>::quiet_NaN(), -3.0f);
  EXPECT_EQ(f.xwidth, 2.0f);
  EXPECT_EQ(f.ywidth, kMinPixelFilterWidth);
  EXPECT_EQ(filter("box", 1e9f, 1).xwidth, kMaxPixelFilterWidth);
}

TEST(PixelFilter, SupportIsHalfTheWidth) {
  const PixelFilter f = filter("gaussian", 3, 5);
  EXPECT_EQ(f.radius_x(), 1.5f);
  EXPECT_EQ(f.radius_y(), 2.5f);
}

TEST(PixelFilter, BoxIsOneInsideAndHalfOpenAtTheEdge) {
  const PixelFilter f = filter("box", 1, 1);
  EXPECT_EQ(f.eval(0, 0), 1.0f);
  EXPECT_EQ(f.eval(0.49f, -0.49f), 1.0f);
  // Pixel i spans [i, i+1): a sample on the boundary belongs to the pixel on its right/below.
  EXPECT_EQ(f.eval(-0.5f, 0), 1.0f);
  EXPECT_EQ(f.eval(0.5f, 0), 0.0f);
  EXPECT_EQ(f.eval(0, 0.5f), 0.0f);
  EXPECT_EQ(f.eval(0.7f, 0), 0.0f);
}

TEST(PixelFilter, TriangleIsSeparableTent) {
  const PixelFilter f = filter("triangle", 2, 4);
  EXPECT_FLOAT_EQ(f.eval(0, 0), 1.0f);
  EXPECT_FLOAT_EQ(f.eval(0.5f, 0), 0.5f);
  EXPECT_FLOAT_EQ(f.eval(0, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(f.eval(0.5f, 1.0f), 0.25f);
  EXPECT_EQ(f.eval(1.0f, 0), 0.0f);
  EXPECT_EQ(f.eval(0, 2.5f), 0.0f);
}

TEST(PixelFilter, GaussianMatchesRiGaussianFilter) {
  // RiGaussianFilter: x *= 2/xwidth; y *= 2/ywidth; exp(-2 (x^2 + y^2)).
  const PixelFilter f = filter("gaussian", 2, 2);
  EXPECT_FLOAT_EQ(f.eval(0, 0), 1.0f);
  EXPECT_NEAR(f.eval(0.5f, 0), std::exp(-0.5f), 1e-6f);
  EXPECT_NEAR(f.eval(0.5f, 0.5f), std::exp(-1.0f), 1e-6f);
  EXPECT_NEAR(f.eval(0.999f, 0), std::exp(-2.0f * 0.999f * 0.999f), 1e-6f);
  EXPECT_EQ(f.eval(1.0f, 0), 0.0f);  // truncated at the support edge
  const PixelFilter wide = filter("gaussian", 4, 2);
  EXPECT_NEAR(wide.eval(1.0f, 0), std::exp(-0.5f), 1e-6f);
  EXPECT_NEAR(wide.eval(1.0f, 0.5f), std::exp(-1.0f), 1e-6f);
}

TEST(PixelFilter, CatmullRomInterpolatesAndHasNegativeLobes) {
  const PixelFilter f = filter("catmull-rom", 4, 4);  // one spline unit per pixel
  EXPECT_FLOAT_EQ(f.eval(0, 0), 1.0f);
  EXPECT_NEAR(f.eval(1.0f, 0), 0.0f, 1e-7f);  // interpolating: zero at the neighbour centres
  EXPECT_NEAR(f.eval(0, 1.0f), 0.0f, 1e-7f);
  EXPECT_FLOAT_EQ(f.eval(0.5f, 0), 0.5625f);   // 1.5 t^3 - 2.5 t^2 + 1 at t = 1/2
  EXPECT_FLOAT_EQ(f.eval(1.5f, 0), -0.0625f);  // -0.5 t^3 + 2.5 t^2 - 4 t + 2 at t = 3/2
  EXPECT_FLOAT_EQ(f.eval(0.5f, 0.5f), 0.5625f * 0.5625f);
  EXPECT_EQ(f.eval(2.0f, 0), 0.0f);
  EXPECT_EQ(f.eval(0, 3.0f), 0.0f);
}

TEST(PixelFilter, SincIsWindowedToZeroAtTheEdge) {
  const PixelFilter f = filter("sinc", 4, 4);
  const float pi = std::numbers::pi_v<float>;
  EXPECT_FLOAT_EQ(f.eval(0, 0), 1.0f);
  EXPECT_NEAR(f.eval(1.0f, 0), 0.0f, 1e-6f);  // sinc zero crossing
  EXPECT_NEAR(f.eval(0.5f, 0), (1.0f / (0.5f * pi)) * std::cos(pi * 0.5f / 4.0f), 1e-6f);
  EXPECT_NEAR(f.eval(1.99f, 0), 0.0f, 1e-3f);  // the window closes continuously
  EXPECT_EQ(f.eval(2.0f, 0), 0.0f);
  EXPECT_LT(f.eval(1.5f, 0), 0.0f);  // negative lobe
}

TEST(PixelFilter, AllFiltersAreSymmetricAndFinite) {
  const char* names[] = {"box", "triangle", "gaussian", "catmull-rom", "sinc"};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const char* name : names) {
    const PixelFilter f = filter(name, 3, 2.5f);
    for (float dx = 0.0f; dx < 1.45f; dx += 0.1f) {
      for (float dy = 0.0f; dy < 1.2f; dy += 0.1f) {
        const float w = f.eval(dx, dy);
        EXPECT_TRUE(std::isfinite(w)) << name;
        EXPECT_EQ(w, f.eval(-dx, dy)) << name << " " << dx << " " << dy;
        EXPECT_EQ(w, f.eval(dx, -dy)) << name << " " << dx << " " << dy;
        EXPECT_EQ(w, f.eval(-dx, -dy)) << name << " " << dx << " " << dy;
      }
    }
    EXPECT_EQ(f.eval(nan, 0), 0.0f) << name;
    EXPECT_EQ(f.eval(0, inf), 0.0f) << name;
    EXPECT_EQ(f.eval(-inf, 0), 0.0f) << name;
    EXPECT_EQ(f.eval(1.6f, 0), 0.0f) << name;  // past the support
  }
}

}  // namespace
}  // namespace darc
