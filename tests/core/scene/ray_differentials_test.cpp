// Secondary-ray footprints (Igehy 1999) against geometry: a flat mirror reflects a footprint into
// the mirrored one, eta 1 refracts nothing, and the refracted direction obeys Snell's law.
#include "core/scene/ray_differentials.h"

#include <gtest/gtest.h>

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

TEST(RayDifferentials, AShadowFootprintKeepsItsSizeAndIsPerpendicularToTheRay) {
  Interaction at = flat_hit({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const Vec3f l = normalize(Vec3f{1, 0, 1});
  RayFootprint f = shadow_footprint(at, l, 0);
  EXPECT_NEAR(dot(f.dox, l), 0.0f, 1e-6f);
  EXPECT_NEAR(dot(f.doy, l), 0.0f, 1e-6f);
  EXPECT_NEAR(f.reach(100), f.reach(0), 1e-6f);
  EXPECT_NEAR(length(f.dox), std::sqrt(0.5f), 1e-6f) << "the footprint as the light sees it";
}

}  // namespace
}  // namespace darc
