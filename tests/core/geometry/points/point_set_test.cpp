// PointSet: the exact hit of a disc facing the ray (at the radius, t, bounds), and the footprint
// coverage of point_set_coverage against the disc's area.
#include "core/geometry/points/point_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/geometry/points/point_set_coverage.h"

namespace darc {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

PointSet one_point(const Vec3f& c, float r) {
  PointSet set;
  set.add(c, r, 0);
  return set;
}

TEST(PointSet, HitsWithinTheRadiusAndMissesJustBeyondIt) {
  const float r = 0.25f;
  const PointSet set = one_point({0, 0, 4}, r);
  float t = -1;
  // Along z: the disc is perpendicular to the ray, so the offset across it is all that counts.
  EXPECT_TRUE(intersect_point(set, 0, Ray{{r * 0.999f, 0, 0}, {0, 0, 1}}, t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  EXPECT_FALSE(intersect_point(set, 0, Ray{{r * 1.001f, 0, 0}, {0, 0, 1}}, t));
  EXPECT_FALSE(intersect_point(set, 0, Ray{{0, -r * 1.001f, 0}, {0, 0, 1}}, t));
}

TEST(PointSet, TIsTheCentresProjectionOnTheRayWhateverItsDirectionsLength) {
  const PointSet set = one_point({3, 4, 0}, 0.5f);
  // A ray with |d| = 10 towards (3, 4, 0) passing 0.3 beside the centre.
  const Vec3f d = Vec3f{0.6f, 0.8f, 0} * 10.0f;
  float t = 0;
  ASSERT_TRUE(intersect_point(set, 0, Ray{{0, 0, 0.3f}, d}, t));
  EXPECT_NEAR(t, 0.5f, 1e-6f) << "the centre is 5 away along a direction of length 10";
  // A ray seen from the side misses when the centre passes outside the disc.
  EXPECT_FALSE(intersect_point(set, 0, Ray{{0, 0, 0.6f}, d}, t));
}

TEST(PointSet, RespectsTheRaysIntervalAndHidesZeroRadius) {
  const PointSet set = one_point({0, 0, 4}, 0.5f);
  float t = 0;
  EXPECT_FALSE(intersect_point(set, 0, Ray{{0, 0, 0}, {0, 0, 1}, 0, 3.9f}, t));
  EXPECT_FALSE(intersect_point(set, 0, Ray{{0, 0, 0}, {0, 0, 1}, 4.1f}, t));
  EXPECT_FALSE(intersect_point(set, 0, Ray{{0, 0, 0}, {0, 0, -1}}, t)) << "behind the origin";
  EXPECT_FALSE(intersect_point(one_point({0, 0, 4}, 0), 0, Ray{{0, 0, 0}, {0, 0, 1}}, t));
  EXPECT_FALSE(intersect_point(set, 0, Ray{{0, 0, 0}, {0, 0, 0}}, t)) << "no direction";
  EXPECT_FALSE(intersect_point(set, 0, Ray{{0, 0, 0}, {0, 0, NAN}}, t));
}

TEST(PointSet, BoundsAreTheCubeAroundTheDisc) {
  const PointSet set = one_point({1, 2, 3}, 0.5f);
  const BBox b = set.bounds(0);
  EXPECT_EQ(b.lo, (Vec3f{0.5f, 1.5f, 2.5f}));
  EXPECT_EQ(b.hi, (Vec3f{1.5f, 2.5f, 3.5f}));
}

TEST(PointSet, ShadingIsSharedWhileItIsTheSame) {
  PointSet set;
  const PointShading red{{1, 0, 0}, {1, 1, 1}}, green{{0, 1, 0}, {0.5f, 0.5f, 0.5f}};
  set.add({0, 0, 0}, 1, 0, red);
  set.add({1, 0, 0}, 1, 0, red);
  set.add({2, 0, 0}, 1, 0, green);
  EXPECT_EQ(set.shading.size(), 2u);
  EXPECT_EQ(set.color(1), (Vec3f{1, 0, 0}));
  EXPECT_EQ(set.opacity(2), (Vec3f{0.5f, 0.5f, 0.5f}));
}

// The coverages of unit footprints tiling the plane (a grid of unit squares, each the footprint
// of a ray through its centre) sum to the disc's area, wherever the disc lies among them.
float summed_coverage(CoverageModel model, float r, float cx, float cy) {
  float sum = 0;
  for (int j = -8; j <= 8; ++j)
    for (int i = -8; i <= 8; ++i) sum += point_coverage(model, cx - float(i), cy - float(j), r, 1, 0, 0, 1);
  return sum;
}

TEST(PointCoverage, SquareFootprintsTilingThePlaneSumToTheDiscsArea) {
  for (float r : {0.05f, 0.3f, 0.5f, 1.7f})
    for (float c : {0.0f, 0.25f, 0.5f, 0.37f}) {
      EXPECT_NEAR(summed_coverage(CoverageModel::Square, r, c, 0.61f * c), kPi * r * r, 1e-4f * (1 + r * r))
          << "radius " << r << " at " << c;
      EXPECT_NEAR(summed_coverage(CoverageModel::Box, r, c, 0.61f * c), kPi * r * r, 1e-4f * (1 + r * r))
          << "radius " << r << " at " << c;
    }
}

TEST(PointCoverage, ADiscInsideTheFootprintCoversItsArea) {
  // A rotated footprint square of side 2: the disc inside it covers pi r^2 / 4 of it.
  const float s = 2.0f * std::sqrt(0.5f);
  for (CoverageModel model : {CoverageModel::Square, CoverageModel::Disc})
    EXPECT_NEAR(point_coverage(model, 0.1f, -0.05f, 0.2f, s, s, -s, s), kPi * 0.04f / 4.0f, 1e-5f) << int(model);
  EXPECT_FLOAT_EQ(point_coverage(CoverageModel::Square, 0, 0, 5, 1, 0, 0, 1), 1.0f) << "larger than the footprint";
  EXPECT_FLOAT_EQ(point_coverage(CoverageModel::Square, 3, 0, 0.5f, 1, 0, 0, 1), 0.0f) << "beside it";
}

TEST(PointCoverage, SquareFootprintsCoverTheExactAreaOfLargeDiscs) {
  // A footprint 4 x 4: a unit disc centred on its corner covers a quarter disc, on the middle of
  // a side half a disc; a footprint 2 x 2 with the disc's centre 1.5 off cuts a circular segment
  // of height 0.5 (area acos(0.5) - 0.5 sqrt(0.75)).
  EXPECT_NEAR(point_coverage(CoverageModel::Square, 2, 2, 1, 4, 0, 0, 4), kPi / 4 / 16, 1e-6f);
  EXPECT_NEAR(point_coverage(CoverageModel::Square, 2, 0, 1, 4, 0, 0, 4), kPi / 2 / 16, 1e-6f);
  EXPECT_NEAR(point_coverage(CoverageModel::Square, 0, -1.5f, 1, 2, 0, 0, 2),
              (std::acos(0.5f) - 0.5f * std::sqrt(0.75f)) / 4, 1e-6f);
  // The same rotated by 30 degrees with the footprint: only the relative placement counts.
  const float c = std::cos(0.5236f), s = std::sin(0.5236f);
  EXPECT_NEAR(point_coverage(CoverageModel::Square, 2 * c - 2 * s, 2 * s + 2 * c, 1, 4 * c, 4 * s, -4 * s, 4 * c),
              kPi / 4 / 16, 1e-5f);
}

TEST(PointCoverage, DiscFootprintIsTheExactLens) {
  // Two unit discs whose centres are 1 apart overlap in 2 pi / 3 - sqrt(3) / 2; the footprint
  // disc of radius 1 has the area of a square of side sqrt(pi).
  const float side = std::sqrt(kPi);
  EXPECT_NEAR(point_coverage(CoverageModel::Disc, 1, 0, 1, side, 0, 0, side), (2 * kPi / 3 - std::sqrt(3.0f) / 2) / kPi,
              1e-5f);
}

TEST(PointDistance, TheFragmentOfAPointSeenThroughAFootprint) {
  const PointSet set = one_point({0.1f, 0, 10}, 0.2f);
  RayFootprint fp;  // an orthographic footprint 1 x 1 everywhere
  fp.dox = {1, 0, 0};
  fp.doy = {0, 1, 0};
  fp.min_radius = 1e-6f;
  const DistanceRay ray = make_distance_ray(Ray{{0, 0, 0}, {0, 0, 2}}, fp);
  PointFragmentHit h;
  ASSERT_TRUE(intersect_point_distance(set, 0, ray, CoverageModel::Square, h, true));
  EXPECT_NEAR(h.t, 5.0f, 1e-6f);
  EXPECT_NEAR(h.coverage, kPi * 0.04f, 1e-5f);
  EXPECT_NEAR(h.distance, 0.1f, 1e-6f);
  EXPECT_EQ(mask_count(h.mask), int(std::lround(kPi * 0.04f * 64))) << "as many mask points as coverage";
  // Beyond the footprint's reach: no fragment.
  const PointSet far = one_point({2, 0, 10}, 0.2f);
  EXPECT_FALSE(intersect_point_distance(far, 0, ray, CoverageModel::Square, h, true));
  // No footprint: the exact hit test.
  RayFootprint none;
  none.min_radius = 1e-6f;
  const DistanceRay exact = make_distance_ray(Ray{{0, 0, 0}, {0, 0, 1}}, none);
  ASSERT_TRUE(intersect_point_distance(set, 0, exact, CoverageModel::Square, h, true));
  EXPECT_EQ(h.coverage, 1.0f);
  EXPECT_FALSE(intersect_point_distance(one_point({0.3f, 0, 10}, 0.2f), 0, exact, CoverageModel::Square, h));
}

}  // namespace
}  // namespace darc
