// Analytic sphere coverage (core/footprint/sphere_coverage.h) against what it replaces: the
// fraction of a dense grid of the footprint's sub-rays that meet the sphere (exact ray tests),
// for camera pencils, shadow pencils toward a point light and parallel (orthographic) footprints;
// and the case the sub-rays cannot see: a sphere far smaller than the footprint between them.
#include "core/footprint/sphere_coverage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace darc {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

FootprintFrame frame_of(const Ray& ray, const RayFootprint& f) {
  FootprintFrame frame;
  EXPECT_TRUE(FootprintFrame::make(ray, f, frame));
  return frame;
}

// A camera ray along +z from the origin whose footprint is `width` wide at distance 1.
FootprintFrame camera_frame(float width) {
  return frame_of(Ray{{0, 0, 0}, {0, 0, 1}, 0, kInf}, pencil_footprint({}, {}, {width, 0, 0}, {0, width, 0}, 0, 0));
}

// Whether the sub-ray (u, v) meets the sphere within the frame's interval (double precision).
bool sub_ray_hits(const FootprintFrame& fr, double u, double v, const Vec3d& c, double r) {
  const Vec3d o = fr.origin(u, v), d = fr.direction(u, v);
  const Vec3d oc = o - c;
  const double a = dot(d, d), b = dot(oc, d), cc = dot(oc, oc) - r * r;
  const double disc = b * b - a * cc;
  if (disc < 0) return false;
  const double t0 = (-b - std::sqrt(disc)) / a, t1 = (-b + std::sqrt(disc)) / a;
  return (t0 >= fr.t_min && t0 <= fr.t_max) || (t1 >= fr.t_min && t1 <= fr.t_max);
}

double brute_coverage(const FootprintFrame& fr, const Vec3d& c, double r, int n = 512) {
  int hits = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) hits += sub_ray_hits(fr, (i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5, c, r);
  return double(hits) / (double(n) * n);
}

TEST(UnitDiscArea, InSquaresAndTriangles) {
  const double big[4][2] = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  EXPECT_NEAR(unit_disc_area_in_polygon(big, 4), std::numbers::pi, 1e-12);
  const double quadrant[4][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  EXPECT_NEAR(unit_disc_area_in_polygon(quadrant, 4), std::numbers::pi / 4, 1e-12);
  const double inside[3][2] = {{0.1, 0.1}, {0.5, 0.1}, {0.1, 0.4}};  // clockwise order is fine too
  EXPECT_NEAR(unit_disc_area_in_polygon(inside, 3), 0.5 * 0.4 * 0.3, 1e-12);
  const double half[4][2] = {{-3, 0}, {3, 0}, {3, 3}, {-3, 3}};
  EXPECT_NEAR(unit_disc_area_in_polygon(half, 4), std::numbers::pi / 2, 1e-12);
  const double away[4][2] = {{2, 2}, {3, 2}, {3, 3}, {2, 3}};
  EXPECT_EQ(unit_disc_area_in_polygon(away, 4), 0.0);
}

TEST(SphereCoverage, ASphereFarSmallerThanTheFootprintCoversItsArea) {
  // Footprint 0.01 wide at depth 1: at depth 5 it is 0.05 wide; a sphere of radius 0.002 (0.04 of
  // the footprint's side) at (u, v) = (1/8, 1/8), between the mask points at odd sixteenths.
  const FootprintFrame fr = camera_frame(0.01f);
  const Vec3d c{0.05 * 0.125, 0.05 * 0.125, 5};
  const double r = 0.002;
  SphereFootprintHit h;
  ASSERT_EQ(sphere_coverage(fr, c, r, h), SphereCoverage::Covered);
  // Its silhouette is a disc of radius r / sqrt(1 - (r / |c|)^2) at depth |c|, seen on a footprint
  // of side 0.05 (to first order in the tiny angles).
  const double expected = std::numbers::pi * r * r / (0.05 * 0.05);
  EXPECT_NEAR(h.coverage, expected, 0.01 * expected);
  EXPECT_EQ(h.mask, 0u) << "no mask point's sub-ray meets it";
  EXPECT_FALSE(h.covers_centre);
  EXPECT_LE(h.t_near, 5 - r);
  EXPECT_GE(h.t_far, 5 + r);
}

TEST(SphereCoverage, MatchesDenseSubRaysForPencils) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> offset(-0.04, 0.04), size(0.002, 0.06), depth(2.0, 6.0);
  const FootprintFrame fr = camera_frame(0.01f);
  int partial = 0;
  for (int i = 0; i < 200; ++i) {
    const double z = depth(rng);
    const Vec3d c{offset(rng) * z, offset(rng) * z, z};
    const double r = size(rng) * z * 0.5;
    SphereFootprintHit h;
    const SphereCoverage result = sphere_coverage(fr, c, r, h);
    ASSERT_NE(result, SphereCoverage::NotAnalytic) << i;
    const double brute = brute_coverage(fr, c, r, 256);
    const double analytic = result == SphereCoverage::Covered ? h.coverage : 0.0;
    EXPECT_NEAR(analytic, brute, 0.01) << "sphere " << i;
    partial += brute > 0.05 && brute < 0.95;
    if (result != SphereCoverage::Covered) continue;
    for (int b = 0; b < kMaskSide * kMaskSide; ++b)
      EXPECT_EQ(bool((h.mask >> b) & 1), sub_ray_hits(fr, mask_point_u(b), mask_point_v(b), c, r))
          << "sphere " << i << " point " << b;
    EXPECT_EQ(h.covers_centre, sub_ray_hits(fr, 0, 0, c, r));
  }
  EXPECT_GT(partial, 20);
}

TEST(SphereCoverage, ALargeSphereAtAWideAngleMatchesDenseSubRays) {
  // A camera ray 35 degrees off the axis toward a sphere's silhouette: the silhouette is an
  // ellipse, curved inside the footprint.
  const Vec3f d = normalize(Vec3f{std::sin(0.61f), 0, std::cos(0.61f)});
  const Vec3f ax = normalize(cross(d, Vec3f{0, 1, 0})) * 0.03f, ay = Vec3f{0, 0.03f, 0};
  const FootprintFrame fr = frame_of(Ray{{0, 0, 0}, d, 0, kInf}, pencil_footprint({}, {}, ax, ay, 0, 0));
  for (double r : {1.0, 1.5, 2.0, 2.2}) {
    const Vec3d c{0, 0, 3};  // angular radius asin(r / 3): 19.5 to 47 degrees
    SphereFootprintHit h;
    const SphereCoverage result = sphere_coverage(fr, c, r, h);
    ASSERT_NE(result, SphereCoverage::NotAnalytic) << r;
    EXPECT_NEAR(result == SphereCoverage::Covered ? h.coverage : 0.0, brute_coverage(fr, c, r), 0.005) << r;
  }
}

TEST(SphereCoverage, ShadowPencilsAndParallelFootprintsMatchDenseSubRays) {
  // A shadow ray from the origin to a point light at (0, 0, 10): its sub-rays meet at the light.
  const Vec3f ddx{0.02f, 0, 0}, ddy{0, 0.02f, 0};
  const FootprintFrame shadow =
      frame_of(Ray{{0, 0, 0}, {0, 0, 1}, 0, 10}, pencil_footprint(ddx * -10.0f, ddy * -10.0f, ddx, ddy, 10, 0));
  ASSERT_EQ(shadow.side, -1);
  // An orthographic footprint 0.1 wide.
  const FootprintFrame parallel = frame_of(
      Ray{{0, 0, 0}, {0, 0, 1}, 0, kInf}, RayFootprint{{0.1f, 0, 0}, {0, 0.1f, 0}, {}, {}, 0, FootprintForm::Parallel, 0});
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> offset(-0.08, 0.08), size(0.005, 0.08), depth(2.0, 7.0);
  for (int i = 0; i < 100; ++i) {
    const Vec3d c{offset(rng), offset(rng), depth(rng)};
    const double r = size(rng);
    for (const FootprintFrame* fr : {&shadow, &parallel}) {
      SphereFootprintHit h;
      const SphereCoverage result = sphere_coverage(*fr, c, r, h);
      ASSERT_NE(result, SphereCoverage::NotAnalytic) << i;
      EXPECT_NEAR(result == SphereCoverage::Covered ? h.coverage : 0.0, brute_coverage(*fr, c, r, 256), 0.01)
          << "sphere " << i << (fr == &shadow ? " shadow" : " parallel");
    }
  }
}

TEST(SphereCoverage, BehindTheCameraOrAroundItOrBeyondTheIntervalIsNotTakenAnalytically) {
  const FootprintFrame fr = camera_frame(0.01f);
  SphereFootprintHit h;
  EXPECT_EQ(sphere_coverage(fr, {0, 0, -5}, 1, h), SphereCoverage::Miss) << "behind the apex";
  EXPECT_EQ(sphere_coverage(fr, {0, 0, 0.5}, 1, h), SphereCoverage::NotAnalytic) << "the apex inside";
  FootprintFrame near = fr;
  near.t_max = 4;
  EXPECT_EQ(sphere_coverage(near, {0, 0, 5}, 0.5, h), SphereCoverage::Miss) << "beyond the interval";
  EXPECT_EQ(sphere_coverage(near, {0, 0, 4}, 0.5, h), SphereCoverage::NotAnalytic) << "across its end";
  EXPECT_EQ(sphere_coverage(fr, {1, 0, 5}, 0.1, h), SphereCoverage::Miss) << "beside the footprint";
  ASSERT_EQ(sphere_coverage(fr, {0, 0, 5}, 1, h), SphereCoverage::Covered);
  EXPECT_EQ(h.coverage, 1.0f);
  EXPECT_EQ(h.mask, kFullMask);
  EXPECT_TRUE(h.covers_centre);
}

}  // namespace
}  // namespace darc
