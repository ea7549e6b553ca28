// The pure parts of the speed-against-error report (bench/): the equal-error interpolation, the
// image comparison and the CSV layout, on synthetic data with analytic answers. The benchmark
// itself never runs under ctest.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "bench/equal_error.h"
#include "bench/image_error.h"
#include "bench/speed_error_report.h"

namespace darc::bench {
namespace {

// A Monte Carlo curve RMSE = c * seconds^-k: a straight line in log-log space.
std::vector<SpeedErrorPoint> power_law_curve(double c, double k) {
  std::vector<SpeedErrorPoint> curve;
  for (double s : {0.1, 0.4, 1.6, 6.4, 25.6}) curve.push_back({s, c * std::pow(s, -k)});
  return curve;
}

TEST(EqualErrorTime, IsExactOnAPowerLawBetweenTwoSettings) {
  const double c = 0.02, k = 0.5;
  std::vector<SpeedErrorPoint> curve = power_law_curve(c, k);
  const double target = 0.01;  // reached at seconds = (c / target)^(1/k) = 4, between 1.6 and 6.4
  EqualErrorTime e = equal_error_time(curve, target);
  EXPECT_EQ(e.kind, EqualErrorKind::Interpolated);
  EXPECT_NEAR(e.seconds, 4.0, 1e-9);
}

TEST(EqualErrorTime, IsExactForAnyPowerLawExponent) {
  const double c = 0.05, k = 0.8;  // jittered sampling converges faster than 1/2
  std::vector<SpeedErrorPoint> curve = power_law_curve(c, k);
  const double target = 0.01;
  EqualErrorTime e = equal_error_time(curve, target);
  EXPECT_EQ(e.kind, EqualErrorKind::Interpolated);
  EXPECT_NEAR(e.seconds, std::pow(c / target, 1 / k), 1e-9);
}

TEST(EqualErrorTime, ATargetEqualToAMeasuredRmseGivesThatSettingsTime) {
  std::vector<SpeedErrorPoint> curve{{1, 0.1}, {2, 0.05}, {8, 0.02}};
  EqualErrorTime e = equal_error_time(curve, 0.05);
  EXPECT_EQ(e.kind, EqualErrorKind::Interpolated);
  EXPECT_NEAR(e.seconds, 2.0, 1e-12);
}

TEST(EqualErrorTime, CheapestSettingAlreadyGoodEnoughIsAnUpperBound) {
  std::vector<SpeedErrorPoint> curve{{1, 0.1}, {2, 0.05}};
  EqualErrorTime e = equal_error_time(curve, 0.2);
  EXPECT_EQ(e.kind, EqualErrorKind::CheapestSuffices);
  EXPECT_EQ(e.seconds, 1.0);
  EXPECT_EQ(format_speedup(e, 0.5), "<= 2");
}

TEST(EqualErrorTime, UnreachedTargetIsALowerBoundAtTheCostliestSetting) {
  std::vector<SpeedErrorPoint> curve{{1, 0.1}, {2, 0.05}, {8, 0.02}};
  EqualErrorTime e = equal_error_time(curve, 0.01);
  EXPECT_EQ(e.kind, EqualErrorKind::NotReached);
  EXPECT_EQ(e.seconds, 8.0);
  EXPECT_EQ(format_speedup(e, 2.0), ">= 4");
}

TEST(EqualErrorTime, TakesTheFirstSettingThatReachesTheTargetOnANonMonotoneCurve) {
  // Noise can make RMSE go up between settings: the cheapest one that reaches the target counts.
  std::vector<SpeedErrorPoint> curve{{1, 0.1}, {2, 0.04}, {4, 0.06}, {8, 0.02}};
  EqualErrorTime e = equal_error_time(curve, 0.05);
  EXPECT_EQ(e.kind, EqualErrorKind::Interpolated);
  EXPECT_GT(e.seconds, 1.0);
  EXPECT_LT(e.seconds, 2.0);
}

TEST(EqualErrorTime, ZeroErrorsAndTimesStayFinite) {
  std::vector<SpeedErrorPoint> curve{{0, 0.1}, {1, 0}};
  EqualErrorTime e = equal_error_time(curve, 0);
  EXPECT_EQ(e.kind, EqualErrorKind::Interpolated);
  EXPECT_TRUE(std::isfinite(e.seconds));
  EXPECT_NEAR(e.seconds, 1.0, 1e-12);
  EXPECT_EQ(equal_error_time({}, 0.1).kind, EqualErrorKind::NotReached);
}

Image constant_image(int w, int h, float rgba) {
  Image im;
  im.width = w, im.height = h;
  im.data_window = {0, 0, w, h};
  im.channel_names = {"R", "G", "B", "A", "Z"};
  im.pixels.assign(size_t(w) * size_t(h) * 5, rgba);
  for (size_t i = 4; i < im.pixels.size(); i += 5) im.pixels[i] = 100;  // depth: not compared
  return im;
}

TEST(CompareRgba, OnePixelOneChannelOff) {
  Image a = constant_image(4, 2, 0.5f), b = constant_image(4, 2, 0.5f);
  b.pixels[(1 * 4 + 3) * 5 + 1] = 0.9f;  // pixel (3, 1), G
  b.pixels[(0 * 4 + 0) * 5 + 4] = 7.0f;  // a depth difference is ignored
  std::optional<ImageError> e = compare_rgba(a, b);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->max_error, 0.4, 1e-6);
  EXPECT_NEAR(e->rmse, std::sqrt(0.4 * 0.4 / 32.0), 1e-6);  // 8 pixels x 4 channels
  EXPECT_EQ(e->pixels, 8);
}

TEST(CompareRgba, ComparesByChannelNameAndRejectsMismatches) {
  Image a = constant_image(2, 2, 0.25f);
  Image rgba_only;  // the cached reference's layout: R, G, B, A
  rgba_only.width = rgba_only.height = 2;
  rgba_only.data_window = {0, 0, 2, 2};
  rgba_only.channel_names = {"R", "G", "B", "A"};
  rgba_only.pixels.assign(16, 0.25f);
  std::optional<ImageError> e = compare_rgba(a, rgba_only);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->rmse, 0.0);
  EXPECT_FALSE(compare_rgba(a, constant_image(3, 2, 0.25f)));
  rgba_only.channel_names[3] = "Z";
  EXPECT_FALSE(compare_rgba(a, rgba_only));
}

TEST(CompareRgba, NonFiniteValuesCountAsFullErrorNotNaN) {
  Image a = constant_image(1, 1, 0.0f), b = constant_image(1, 1, 0.0f);
  b.pixels[0] = std::nanf("");
  std::optional<ImageError> e = compare_rgba(a, b);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->max_error, 1.0);
  EXPECT_NEAR(e->rmse, 0.5, 1e-12);  // sqrt(1 / 4)
}

TEST(SpeedErrorCsv, HasTheDocumentedColumnsAndSamplesPerPixel) {
  std::vector<Measurement> rows{{"furball", "distance", 2, 1.5, 3, {0.01, 0.2, 64}},
                                {"grass", "stochastic", 16, 42.0, 1, {0.002, 0.05, 64}}};
  std::ostringstream out;
  write_speed_error_csv(out, rows);
  std::istringstream in(out.str());
  std::string header, first, second, extra;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(header, "scene,hider,samples,seconds,rmse,max_error");
  EXPECT_EQ(first, "furball,distance,4,1.5,0.01,0.2");
  EXPECT_EQ(second, "grass,stochastic,256,42,0.002,0.05");
  EXPECT_FALSE(std::getline(in, extra));
}

}  // namespace
}  // namespace darc::bench
