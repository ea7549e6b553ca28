// Secondary-ray footprints (Igehy 1999) against geometry: a flat mirror reflects a footprint into
// the mirrored one, eta 1 refracts nothing, and the refracted direction obeys Snell's law.
#include "core/scene/ray_differentials.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include <cmath>

namespace darc {
namespace {

void expect_near(const Vec3f& a, const Vec3f& b, float tol, const char* what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

// A pinhole footprint: rays from the origin, neighbours 0.01 apart in direction.
RayFootprint pinhole() {
  RayFootprint f;
  f.ddx = {0.01f, 0, 0};
  f.ddy = {0, 0.01f, 0};
  return f;
}

Interaction flat_hit(const Vec3f& p, const Vec3f& dpdx, const Vec3f& dpdy) {
  Interaction it;
  it.P = p;
  it.dPdx = dpdx;
  it.dPdy = dpdy;
  return it;
}

TEST(RayDifferentials, AFlatMirrorReflectsTheFootprintIntoTheMirroredOne) {
  // Straight down the z axis onto the mirror z = 10 (normal facing the ray: -z).
  const Vec3f d{0, 0, 1}, n{0, 0, -1};
  RayFootprint in = pinhole();
  Interaction at = flat_hit({0, 0, 10}, in.axis_x(10), in.axis_y(10));
  RayFootprint out = reflected_footprint(at, d, n, {}, {}, in);
  // The mirrored camera sits at z = 20 looking down -z: at distance s from the mirror its
  // footprint is (10 + s) * 0.01, as the reflected one.
  for (float s : {0.0f, 5.0f, 30.0f}) {
    expect_near(out.axis_x(s), Vec3f{0.01f * (10 + s), 0, 0}, 1e-6f, "x axis");
    expect_near(out.axis_y(s), Vec3f{0, 0.01f * (10 + s), 0}, 1e-6f, "y axis");
  }
}

TEST(RayDifferentials, EtaOneRefractsNothing) {
  const Vec3f d = normalize(Vec3f{0.3f, -0.2f, 1}), n = normalize(Vec3f{0.1f, 0.2f, -1});
  Vec3f t;
  ASSERT_TRUE(refract(d, n, 1.0f, t));
  expect_near(t, d, 1e-6f, "direction");
  RayFootprint in = pinhole();
  Interaction at = flat_hit({0, 0, 10}, in.axis_x(10), in.axis_y(10));
  RayFootprint out = refracted_footprint(at, d, n, {}, {}, 1.0f, t, in);
  expect_near(out.ddx, in.ddx, 1e-6f, "direction differential");
  expect_near(out.ddy, in.ddy, 1e-6f, "direction differential");
}

TEST(RayDifferentials, RefractionObeysSnellAndReportsTotalInternalReflection) {
  const float eta = 1 / 1.5f, angle = 0.6f;
  const Vec3f n{0, 0, -1}, d{std::sin(angle), 0, std::cos(angle)};
  Vec3f t;
  ASSERT_TRUE(refract(d, n, eta, t));
  EXPECT_NEAR(std::sin(angle), 1.5f * std::sqrt(t.x * t.x + t.y * t.y), 1e-6f) << "n1 sin i = n2 sin t";
  EXPECT_NEAR(length(t), 1.0f, 1e-6f);
  const Vec3f steep{std::sin(1.0f), 0, std::cos(1.0f)};  // 57 degrees, leaving glass
  EXPECT_FALSE(refract(steep, n, 1.5f, t));
}

// Toward a point light the shadow footprint is a pencil: every sub-ray starts on the receiving
// patch and reaches the light at t = distance, where the reach is 0.
TEST(RayDifferentials, AShadowFootprintTowardALightIsAPencilFromThePatchToTheLight) {
  Interaction at = flat_hit({0, 0, 0}, {0.1f, 0, 0}, {0, 0.1f, 0});
  const Vec3f light{3, 1, 4};
  const float distance = length(light - at.P);
  const Vec3f l = (light - at.P) * (1.0f / distance);
  RayFootprint f = shadow_footprint(at, distance, 0);
  EXPECT_EQ(f.form, FootprintForm::Pencil);
  for (float u : {-0.5f, 0.5f})
    for (float v : {-0.5f, 0.5f}) {
      const Vec3f origin = f.dox * u + f.doy * v;  // relative to P
      EXPECT_NEAR(origin.z, 0.0f, 1e-7f) << "sub-rays start on the receiver's plane";
      const Vec3f end = origin + (l + f.ddx * u + f.ddy * v) * distance;
      EXPECT_NEAR(length(end - light), 0.0f, 1e-5f) << "and meet at the light";
    }
  const ReachBound reach = f.reach_bound();
  EXPECT_NEAR(reach.at(distance), 0.0f, 1e-6f);
  EXPECT_NEAR(reach.at(0), 0.5f * (0.1f + 0.1f), 1e-6f);
  EXPECT_NEAR(reach.at(0.5f * distance), 0.5f * reach.at(0), 1e-6f) << "halfway to the light, half the size";
  // Over an interval the largest reach is at its near end (the footprint shrinks).
  EXPECT_FLOAT_EQ(reach.max_over(1, 2), reach.at(1));
}

// Toward a distant light it is a prism of the patch: the same size all the way.
TEST(RayDifferentials, AShadowFootprintTowardADistantLightKeepsItsSize) {
  Interaction at = flat_hit({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  RayFootprint f = shadow_footprint(at, std::numeric_limits<float>::infinity(), 0);
  EXPECT_EQ(f.form, FootprintForm::Parallel);
  EXPECT_EQ(f.ddx, Vec3f{});
  EXPECT_NEAR(f.reach(100), f.reach(0), 1e-6f);
  EXPECT_NEAR(length(f.dox), 1.0f, 1e-6f) << "the receiving patch itself, in its tangent plane";
}

// The reach bound is exact for a camera pencil (today's formula), and for any footprint never
// below the true reach, which is convex in t.
// A general footprint with random origin and direction differentials.
RayFootprint random_footprint(std::mt19937& rng) {
  std::uniform_real_distribution<float> c(-1, 1);
  auto vec = [&] { return Vec3f{c(rng), c(rng), c(rng)}; };
  RayFootprint f;
  f.dox = vec() * 0.1f;
  f.doy = vec() * 0.1f;
  f.ddx = vec() * 0.01f;
  f.ddy = vec() * 0.01f;
  return f;
}

TEST(RayDifferentials, TheReachBoundHoldsTheTrueReachOfAnyFootprint) {
  std::mt19937 rng(5);
  for (int i = 0; i < 2000; ++i) {
    const RayFootprint f = random_footprint(rng);
    const ReachBound bound = f.reach_bound();
    for (float t : {0.0f, 0.5f, 3.0f, 10.0f, 40.0f}) {
      const float exact = 0.5f * (length(f.axis_x(t)) + length(f.axis_y(t)));
      EXPECT_GE(bound.at(t) * (1 + 1e-5f) + 1e-7f, exact) << i << " at " << t;
    }
  }
  RayFootprint camera = pencil_footprint({}, {}, {0.01f, 0, 0}, {0, 0.02f, 0}, 0, 0);
  EXPECT_FLOAT_EQ(camera.reach(10), 0.5f * (0.01f + 0.02f) * 10);
}

// The walk's reach: no footprint corner (sub-ray u, v = +-1/2) is farther from the ray at any t,
// it never exceeds reach_bound, and for a square pixel it is the half-diagonal, 1/sqrt 2 of
// reach_bound's half-sum.
TEST(RayDifferentials, TheWalkReachHoldsEveryCornerOfTheFootprint) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> apex(0, 10);
  for (int i = 0; i < 2000; ++i) {
    RayFootprint f = random_footprint(rng);
    if (i % 3 == 1) f.form = FootprintForm::Pencil, f.apex_t = apex(rng);
    const ReachBound walk = f.walk_reach_bound(), loose = f.reach_bound();
    for (float t : {0.0f, 0.5f, 3.0f, 10.0f, 40.0f}) {
      for (float u : {-0.5f, 0.5f})
        for (float v : {-0.5f, 0.5f}) {
          const float corner = length(f.axis_x(t) * u + f.axis_y(t) * v);
          EXPECT_GE(walk.at(t) * (1 + 1e-5f) + 1e-7f, corner) << i << " at " << t;
        }
      EXPECT_LE(walk.at(t), loose.at(t) * (1 + 1e-6f)) << i << " at " << t;
    }
  }
  RayFootprint camera = pencil_footprint({}, {}, {0.01f, 0, 0}, {0, 0.01f, 0}, 0, 0);
  EXPECT_NEAR(camera.walk_reach_bound().at(10), std::sqrt(0.5f) * camera.reach(10), 1e-7f);
}

}  // namespace
}  // namespace darc
