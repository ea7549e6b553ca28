// RenderMan 21+ area lights as darc lights: the light they send against the radiometry of the
// emitters they stand for (a one-sided Lambertian square, a sphere), built from RIB by
// SceneBuilder and evaluated by make_lights.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/scenes_from_rib.h"
#include "shading/lights.h"

namespace darc {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<std::unique_ptr<Light>> lights_of(const std::string& world_body) {
  test::Built b = test::build("WorldBegin\n" + world_body + "\nWorldEnd\n");
  EXPECT_EQ(b.scenes.size(), 1u);
  Diagnostics diag([](const Diagnostic&) {});
  return make_lights(b.scenes.at(0).lights, diag);
}

// The light arriving at P (its red channel), 0 when none.
double arriving(const Light& l, Vec3f P, Vec3f* L = nullptr) {
  LightContribution c;
  if (!l.illuminate(P, c)) return 0;
  if (L) *L = c.L;
  return c.Cl.x;
}

TEST(RisLights, ARectLightSendsLTimesAreaTimesCosineOverDistanceSquaredOnItsLitSide) {
  // Radiance 1.5 on a 2 x 2 square in the z = 0 plane, lit side -z.
  const auto lights = lights_of("Scale 2 2 1\nLight \"PxrRectLight\" \"r\" \"float intensity\" [1.5]");
  ASSERT_EQ(lights.size(), 1u);
  const double L = 1.5, A = 4, d = 20;
  Vec3f dir;
  EXPECT_NEAR(arriving(*lights[0], {0, 0, float(-d)}, &dir), L * A / (d * d), 1e-6);
  EXPECT_NEAR(dir.z, 1, 1e-6) << "L points back at the light";
  const double a = kPi / 3;
  const Vec3f oblique{float(d * std::sin(a)), 0, float(-d * std::cos(a))};
  EXPECT_NEAR(arriving(*lights[0], oblique), L * A * std::cos(a) / (d * d), 1e-6);
  EXPECT_EQ(arriving(*lights[0], {0, 0, float(d)}), 0) << "nothing behind a one-sided emitter";
}

TEST(RisLights, ARectLightsPowerIsPiTimesRadianceTimesArea) {
  const auto lights = lights_of("Scale 3 1 1\nLight \"PxrRectLight\" \"r\" \"float intensity\" [2]");
  ASSERT_EQ(lights.size(), 1u);
  // Power = integral over directions of (light arriving at distance R) * R^2, by a midpoint rule
  // in (cos theta, phi) about the z axis.
  const double R = 100;
  const int n = 400;
  double power = 0;
  for (int i = 0; i < n; ++i) {
    const double z = -1 + (i + 0.5) * 2.0 / n;
    const double s = std::sqrt(1 - z * z);
    for (int j = 0; j < n; ++j) {
      const double phi = (j + 0.5) * 2 * kPi / n;
      const Vec3f P{float(R * s * std::cos(phi)), float(R * s * std::sin(phi)), float(R * z)};
      power += arriving(*lights[0], P) * R * R * (2.0 / n) * (2 * kPi / n);
    }
  }
  EXPECT_NEAR(power, kPi * 2 * 3, 0.01 * kPi * 2 * 3);
}

TEST(RisLights, ASphereLightsIrradianceIsExactOutsideIt) {
  // A sphere of radius r and radiance L gives pi * L * r^2 / d^2 facing it at distance d.
  const auto lights = lights_of(
      "Translate 0 1 0 Scale 2 2 2\nLight \"PxrSphereLight\" \"s\" \"float exposure\" [1] \"color lightColor\" [0.5 1 "
      "1]");
  ASSERT_EQ(lights.size(), 1u);
  const double L = 2 * 0.5, r = 1;
  for (double d : {1.5, 3.0, 10.0})
    EXPECT_NEAR(arriving(*lights[0], {0, float(1 + d), 0}), kPi * L * r * r / (d * d), 1e-6);
}

}  // namespace
}  // namespace darc
