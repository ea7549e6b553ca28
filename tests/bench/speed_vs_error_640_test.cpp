// The pure parts of the 640x480 report (bench/speed_error_640.h, bench/process_memory.h): work
// per ray, the equal-error speed-up against a second baseline, the 640 CSV, and the parsing of
// /proc/self/status, on synthetic data with analytic answers.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "bench/process_memory.h"
#include "bench/speed_error_640.h"

namespace darc::bench {
namespace {

TEST(StatusFieldBytes, ReadsKibibytesOfTheNamedFieldOnly) {
  const std::string status =
      "Name:\tspeed_vs_error\nVmPeak:\t  900 kB\nVmHWMx:\t 1 kB\nVmHWM:\t  2048 kB\nVmRSS:\t  1024 kB\n";
  EXPECT_EQ(status_field_bytes(status, "VmHWM"), 2048u * 1024u);
  EXPECT_EQ(status_field_bytes(status, "VmRSS"), 1024u * 1024u);
  EXPECT_FALSE(status_field_bytes(status, "VmSwap"));
  EXPECT_FALSE(status_field_bytes("VmRSS:\tlots\n", "VmRSS"));
  EXPECT_FALSE(status_field_bytes("VmRSS:\t12 MB\n", "VmRSS"));  // only the kernel's kB is understood
}

TEST(WorkRatios, AreZeroWithoutCountsAndExactOtherwise) {
  EXPECT_EQ(per_ray(10, 0), 0.0);
  EXPECT_DOUBLE_EQ(per_ray(30, 4), 7.5);
  EXPECT_EQ(ns_per_segment_test(2.0, 2, 0), 0.0);
  EXPECT_DOUBLE_EQ(ns_per_segment_test(2.0, 2, 4'000'000'000ull), 1.0);  // 4 thread-seconds / 4e9 tests
  EXPECT_EQ(bytes_per_segment(100, 0), 0.0);
  EXPECT_DOUBLE_EQ(bytes_per_segment(3000, 30), 100.0);
}

// A scene with the distance hider at 1x1 (RMSE 0.01, 1 s) and two baselines on power laws
// RMSE = c * seconds^-1/2 measured at 1, 4, 16, 64 s.
SceneReport two_baseline_scene(double c_stochastic, double c_embree) {
  SceneReport s;
  s.name = "hairball";
  s.settings.push_back({"hairball", "distance", 1, 1.0, 1, {0.01, 0.1, 4}});
  int n = 1;  // the N of N x N: 1, 2, 4, 8
  for (double t : {1.0, 4.0, 16.0, 64.0}) {
    s.settings.push_back({"hairball", "stochastic", n, t, 1, {c_stochastic / std::sqrt(t), 0.5, 4}});
    s.settings.push_back({"hairball", "embree", n, t / 4, 1, {c_embree / std::sqrt(t / 4), 0.5, 4}});
    n *= 2;
  }
  return s;
}

TEST(EqualErrorSpeedup, IsReadOffTheChosenBaselinesOwnCurve) {
  // stochastic reaches 0.01 at (0.04 / 0.01)^2 = 16 s; embree at (0.02 / 0.01)^2 = 4 s.
  SceneReport s = two_baseline_scene(0.04, 0.02);
  std::optional<EqualErrorSpeedup> st = equal_error_speedup(s, 1, "stochastic");
  std::optional<EqualErrorSpeedup> em = equal_error_speedup(s, 1, "embree");
  ASSERT_TRUE(st && em);
  EXPECT_EQ(st->baseline.kind, EqualErrorKind::Interpolated);
  EXPECT_NEAR(st->ratio(), 16.0, 1e-9);
  EXPECT_EQ(em->baseline.kind, EqualErrorKind::Interpolated);
  EXPECT_NEAR(em->ratio(), 4.0, 1e-9);
  EXPECT_EQ(em->text(), "4");
}

TEST(EqualErrorSpeedup, MissingSettingsGiveNothingAndBoundsStayBounds) {
  SceneReport s = two_baseline_scene(0.04, 0.001);  // embree's cheapest setting already beats 0.01
  EXPECT_FALSE(equal_error_speedup(s, 2, "stochastic"));  // no distance 2x2
  EXPECT_FALSE(equal_error_speedup(s, 1, "nonexistent"));
  std::optional<EqualErrorSpeedup> em = equal_error_speedup(s, 1, "embree");
  ASSERT_TRUE(em);
  EXPECT_EQ(em->baseline.kind, EqualErrorKind::CheapestSuffices);
  EXPECT_EQ(em->text(), "<= 0.25");
}

TEST(HiderCurve, KeepsOnlyThatHiderInMeasuredOrder) {
  SceneReport s = two_baseline_scene(0.04, 0.02);
  std::vector<SpeedErrorPoint> curve = hider_curve(s, "embree");
  ASSERT_EQ(curve.size(), 4u);
  EXPECT_DOUBLE_EQ(curve[0].seconds, 0.25);
  EXPECT_DOUBLE_EQ(curve[3].seconds, 16.0);
  EXPECT_TRUE(hider_curve(s, "none").empty());
}

TEST(SpeedError640Csv, HasWorkPerRayColumns) {
  SceneReport s;
  s.name = "grass";
  s.reference_samples_per_axis = 16;
  s.settings.push_back({"grass", "distance", 2, 2.0, 1, {0.01, 0.2, 4}});
  s.settings.push_back({"grass", "embree", 1, 0.5, 1, {0.02, 0.3, 4}});
  WorkCounters d;
  d.primary_rays = 100, d.segment_tests = 2500, d.fragments = 300, d.cells_visited = 1000;
  d.surface_tests = 50, d.surface_pieces = 120, d.shadow_rays = 400, d.shadow_segment_tests = 1000;
  WorkCounters e;
  e.primary_rays = 100, e.intersect_calls = 150;
  s.work = {d, e};
  std::ostringstream out;
  write_speed_error_640_csv(out, std::span<const SceneReport>(&s, 1), 2, 32);
  std::istringstream in(out.str());
  std::string header, first, second, extra;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(header, kCsv640Header);
  // 2 s x 2 threads / 2500 tests = 1.6e6 ns per test.
  EXPECT_EQ(first, "grass,distance,4,2,0.01,0.2,256,25,3,10,0,1.6e+06,0.5,1.2,4,2.5");
  EXPECT_EQ(second, "grass,embree,1,0.5,0.02,0.3,256,0,0,0,1.5,0,0,0,0,0");
  EXPECT_FALSE(std::getline(in, extra));
}

}  // namespace
}  // namespace darc::bench
