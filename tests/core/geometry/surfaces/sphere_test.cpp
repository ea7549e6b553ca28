#include "core/geometry/surfaces/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace darc {
namespace {

constexpr float kTol = 1e-5f;

void expect_vec_near(const Vec3f& a, const Vec3f& b, float tol = kTol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

Sphere unit_sphere() { return Sphere::make(1, -1, 1, 360, Matrix4::identity()); }

TEST(Sphere, HitFromOutsideAlongAxis) {
  Sphere s = Sphere::make(2, -2, 2, 360, Matrix4::identity());
  SurfaceHit h;
  ASSERT_TRUE(s.intersect(Ray{{0, 0, -10}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.t, 8.0f, kTol);
  expect_vec_near(h.p, {0, 0, -2});
  expect_vec_near(h.ng, {0, 0, -1});  // outward at the bottom pole
}

TEST(Sphere, HitFromInsideIsFarSideWithOutwardNormal) {
  SurfaceHit h;
  ASSERT_TRUE(unit_sphere().intersect(Ray{{0, 0, 0}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.t, 1.0f, kTol);
  expect_vec_near(h.ng, {1, 0, 0});  // not flipped toward the ray
}

TEST(Sphere, OffsetRayAnalyticDistance) {
  // Ray parallel to z at distance 0.6 from the axis: hits at z = -sqrt(1 - 0.36) = -0.8.
  SurfaceHit h;
  ASSERT_TRUE(unit_sphere().intersect(Ray{{0.6f, 0, -5}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.t, 4.2f, kTol);
  expect_vec_near(h.ng, {0.6f, 0, -0.8f});
}

TEST(Sphere, RespectsRayInterval) {
  SurfaceHit h;
  Ray r{{0, 0, -5}, {0, 0, 1}};
  r.tmax = 3.9f;
  EXPECT_FALSE(unit_sphere().intersect(r, h));
  r.tmax = 100;
  r.tmin = 4.5f;  // skips the near hit at 4, finds the far one at 6
  ASSERT_TRUE(unit_sphere().intersect(r, h));
  EXPECT_NEAR(h.t, 6.0f, kTol);
}

TEST(Sphere, MissesWhenOffToTheSide) {
  SurfaceHit h;
  EXPECT_FALSE(unit_sphere().intersect(Ray{{1.01f, 0, -5}, {0, 0, 1}}, h));
  EXPECT_FALSE(unit_sphere().intersect(Ray{{0, 0, 5}, {0, 0, 1}}, h));  // sphere behind the ray
}

TEST(Sphere, ZClipPassesThroughToFarSide) {
  // Keep only z in [-0.5, 0.5]: a ray along z through the centre crosses the caps' holes.
  Sphere band = Sphere::make(1, -0.5, 0.5, 360, Matrix4::identity());
  SurfaceHit h;
  EXPECT_FALSE(band.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, h));
  // A slanted ray that enters through the cut bottom cap and leaves through the band.
  // From (0,0,-5) toward (0.9, 0, 0.4359) on the sphere (z within the band).
  Vec3f target{0.9f, 0, std::sqrt(1 - 0.81f)};
  Vec3f o{0, 0, -5};
  Ray r{o, normalize(target - o)};
  ASSERT_TRUE(band.intersect(r, h));
  expect_vec_near(h.p, target, 1e-4f);
  EXPECT_GT(dot(h.ng, r.d), 0.0f);  // far side: outward normal faces away from the ray
}

TEST(Sphere, ZClampedToRadius) {
  Sphere s = Sphere::make(1, -5, 5, 360, Matrix4::identity());
  EXPECT_DOUBLE_EQ(s.zmin, -1);
  EXPECT_DOUBLE_EQ(s.zmax, 1);
  SurfaceHit h;
  EXPECT_TRUE(s.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, h));
}

TEST(Sphere, ThetaMaxQuarter) {
  Sphere quarter = Sphere::make(1, -1, 1, 90, Matrix4::identity());
  SurfaceHit h;
  // Along -x from +x outside: the near point (1,0,0) is at theta 0 (kept), u = 0.
  ASSERT_TRUE(quarter.intersect(Ray{{5, 0.001f, 0}, {-1, 0, 0}}, h));
  EXPECT_NEAR(h.t, 4.0f, 1e-4f);
  EXPECT_NEAR(h.u, 0.0f, 1e-3f);
  // A ray through the cut part (theta 180 first, then 0) finds the kept far side.
  ASSERT_TRUE(quarter.intersect(Ray{{-5, 0.5f, 0}, {1, 0, 0}}, h));
  expect_vec_near(h.p, {std::sqrt(0.75f), 0.5f, 0}, 1e-5f);
  EXPECT_NEAR(h.u, std::atan2(0.5f, std::sqrt(0.75f)) / (std::numbers::pi_v<float> / 2), 1e-5f);
  // Entirely in the third quadrant: misses.
  EXPECT_FALSE(quarter.intersect(Ray{{-0.5f, -0.5f, -5}, {0, 0, 1}}, h));
  // Through theta = 45 degrees quadrant along z: hits the bottom with u = 0.5.
  ASSERT_TRUE(quarter.intersect(Ray{{0.5f, 0.5f, -5}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.u, 0.5f, 1e-5f);
}

TEST(Sphere, NegativeThetaMaxSweepsClockwise) {
  Sphere s = Sphere::make(1, -1, 1, -90, Matrix4::identity());
  SurfaceHit h;
  EXPECT_FALSE(s.intersect(Ray{{0.5f, 0.5f, -5}, {0, 0, 1}}, h));
  ASSERT_TRUE(s.intersect(Ray{{0.5f, -0.5f, -5}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.u, 0.5f, 1e-5f);
  EXPECT_GT(h.ng.z, 0.0f);  // parametric normal flipped: inward at the bottom
}

TEST(Sphere, VRunsFromZminToZmax) {
  Sphere s = Sphere::make(1, 0, 1, 360, Matrix4::identity());
  SurfaceHit h;
  ASSERT_TRUE(s.intersect(Ray{{0, 0, 5}, {0, 0, -1}}, h));  // top pole
  EXPECT_NEAR(h.v, 1.0f, 1e-5f);
  // Equator, z = 0: v = 0.
  ASSERT_TRUE(s.intersect(Ray{{5, 0, 1e-6f}, {-1, 0, 0}}, h));
  EXPECT_NEAR(h.v, 0.0f, 1e-3f);
}

TEST(Sphere, NegativeRadiusFlipsNormal) {
  Sphere s = Sphere::make(-1, -1, 1, 360, Matrix4::identity());
  SurfaceHit h;
  ASSERT_TRUE(s.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.t, 4.0f, kTol);
  expect_vec_near(h.ng, {0, 0, 1});
}

TEST(Sphere, TransformedSphere) {
  // Object scaled by (2, 1, 1) then moved to (10, 0, 0): an ellipsoid.
  Matrix4 m = Matrix4::scale({2, 1, 1}) * Matrix4::translate({10, 0, 0});
  Sphere s = Sphere::make(1, -1, 1, 360, m);
  SurfaceHit h;
  ASSERT_TRUE(s.intersect(Ray{{0, 0, 0}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.t, 8.0f, kTol);
  expect_vec_near(h.ng, {-1, 0, 0});
  // At object point (cos45, sin45, 0) -> world (10 + 2 cos45, sin45, 0); the ellipsoid normal
  // there is proportional to (x/4, y/1) = (cos45/2, sin45).
  float c = std::sqrt(0.5f);
  Vec3f target{10 + 2 * c, c, 0};
  Vec3f o{10, 0, -0.0f};
  ASSERT_TRUE(s.intersect(Ray{o, normalize(target - o)}, h));
  expect_vec_near(h.p, target, 1e-5f);
  expect_vec_near(h.ng, normalize(Vec3f{c / 2, c, 0}), 1e-5f);
  BBox b = s.bounds();
  EXPECT_LE(b.lo.x, 8.0f);
  EXPECT_GE(b.hi.x, 12.0f);
  EXPECT_NEAR(b.lo.x, 8.0f, 1e-4f);
}

TEST(Sphere, MirroredTransformKeepsOutwardNormal) {
  Sphere s = Sphere::make(1, -1, 1, 360, Matrix4::scale({-1, 1, 1}));
  SurfaceHit h;
  ASSERT_TRUE(s.intersect(Ray{{5, 0, 0}, {-1, 0, 0}}, h));
  expect_vec_near(h.ng, {1, 0, 0});
}

TEST(Sphere, GrazingRayTouchesOrMissesWithoutNaN) {
  SurfaceHit h;
  Ray grazing{{1, 0, -5}, {0, 0, 1}};
  if (unit_sphere().intersect(grazing, h)) {
    EXPECT_NEAR(h.t, 5.0f, 1e-3f);
    EXPECT_FALSE(std::isnan(h.ng.x) || std::isnan(h.ng.y) || std::isnan(h.ng.z));
    EXPECT_NEAR(length(h.ng), 1.0f, 1e-5f);
  }
  EXPECT_FALSE(unit_sphere().intersect(Ray{{1.0001f, 0, -5}, {0, 0, 1}}, h));
}

TEST(Sphere, FarOriginKeepsPrecision) {
  // Origin 1e6 away: b^2 - ac would lose every digit of a unit sphere in float; the robust
  // discriminant still finds the analytic hit.
  SurfaceHit h;
  ASSERT_TRUE(unit_sphere().intersect(Ray{{0.5f, 0, -1e6f}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.p.z, -std::sqrt(0.75f), 1e-3f);
}

TEST(Sphere, DegenerateInputNeverHitsNorProducesNaN) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  SurfaceHit h;
  Ray r{{0, 0, -5}, {0, 0, 1}};
  EXPECT_FALSE(Sphere::make(0, -1, 1, 360, Matrix4::identity()).intersect(r, h));
  EXPECT_FALSE(Sphere::make(1, 0.5, 0.5, 360, Matrix4::identity()).intersect(r, h));
  EXPECT_FALSE(Sphere::make(1, -1, 1, 0, Matrix4::identity()).intersect(r, h));
  EXPECT_FALSE(Sphere::make(1, -1, 1, 360, Matrix4::scale({0, 1, 1})).intersect(r, h));
  EXPECT_FALSE(Sphere::make(nan, -1, 1, 360, Matrix4::identity()).intersect(r, h));
  EXPECT_TRUE(Sphere::make(0, -1, 1, 360, Matrix4::identity()).bounds().empty());
  EXPECT_FALSE(unit_sphere().intersect(Ray{{0, 0, -5}, {0, 0, 0}}, h));
  EXPECT_FALSE(unit_sphere().intersect(Ray{{0, 0, -5}, {nan, 0, 1}}, h));
}

TEST(Sphere, RandomRaysGiveUnitNormalsOnTheSurface) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-3, 3);
  Sphere s = Sphere::make(1.5, -1, 1.2, 270, Matrix4::rotate(30, {1, 1, 0}) * Matrix4::translate({0.5, 0, 0}));
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Ray r{{u(rng), u(rng), u(rng)}, normalize(Vec3f{u(rng), u(rng), u(rng)})};
    SurfaceHit h;
    if (!s.intersect(r, h)) continue;
    ++hits;
    ASSERT_NEAR(length(h.ng), 1.0f, 1e-5f);
    Vec3d obj = s.world_to_object.transform_point(Vec3d(h.p));
    ASSERT_NEAR(length(obj), 1.5, 1e-4);
    ASSERT_GE(obj.z, -1 - 1e-4);
    ASSERT_LE(obj.z, 1.2 + 1e-4);
    ASSERT_GE(h.u, 0.0f);
    ASSERT_LE(h.u, 1.0f);
    ASSERT_GE(h.v, 0.0f);
    ASSERT_LE(h.v, 1.0f);
    BBox b = s.bounds();
    ASSERT_TRUE(h.p.x >= b.lo.x && h.p.x <= b.hi.x && h.p.y >= b.lo.y && h.p.y <= b.hi.y && h.p.z >= b.lo.z &&
                h.p.z <= b.hi.z);
  }
  EXPECT_GT(hits, 100);
}

}  // namespace
}  // namespace darc
