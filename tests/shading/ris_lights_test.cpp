// RenderMan 21+ area lights as darc's area lights: the irradiance their samples give against the
// radiometry of the emitters (a one-sided Lambertian square, a sphere), built from RIB by
// SceneBuilder and made by make_lights.
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

// The irradiance at P on a surface of normal N, from a 64 x 64 grid of the light's samples.
double irradiance(const Light& l, Vec3f P, Vec3f N) {
  double sum = 0;
  constexpr int kSide = 64;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      LightContribution c;
      if (l.sample(P, (i + 0.5f) / kSide, (j + 0.5f) / kSide, c)) sum += c.Cl.x * std::max(0.0f, dot(N, c.L));
    }
  return kPi * sum / (kSide * kSide);
}

TEST(RisLights, ARectLightGivesLTimesAreaTimesCosineOverDistanceSquaredFarAwayOnItsLitSide) {
  // Radiance 1.5 on a 2 x 2 square in the z = 0 plane, lit side +z (lookdev.md §2.2). At 10 times
  // its size a square gives its far-field value within 0.5 % (its edges are a little farther).
  const auto lights = lights_of("Scale 2 2 1\nLight \"PxrRectLight\" \"r\" \"float intensity\" [1.5]");
  ASSERT_EQ(lights.size(), 1u);
  ASSERT_GT(lights[0]->samples(), 0);
  const double L = 1.5, A = 4, d = 20;
  EXPECT_NEAR(irradiance(*lights[0], {0, 0, float(d)}, {0, 0, -1}), L * A / (d * d), 5e-3 * L * A / (d * d));
  const double a = kPi / 3;
  const Vec3f oblique{float(d * std::sin(a)), 0, float(d * std::cos(a))};
  EXPECT_NEAR(irradiance(*lights[0], oblique, -normalize(oblique)), L * A * std::cos(a) / (d * d),
              5e-3 * L * A / (d * d));
  EXPECT_EQ(irradiance(*lights[0], {0, 0, float(-d)}, {0, 0, 1}), 0) << "nothing behind a one-sided emitter";
}

TEST(RisLights, ASphereLightsIrradianceIsExactOutsideIt) {
  // A sphere of radius r and radiance L gives pi * L * r^2 / d^2 facing it at distance d.
  const auto lights = lights_of(
      "Translate 0 1 0 Scale 2 2 2\nLight \"PxrSphereLight\" \"s\" \"float exposure\" [1] \"color lightColor\" [0.5 1 "
      "1]");
  ASSERT_EQ(lights.size(), 1u);
  const double L = 2 * 0.5, r = 1;
  for (double d : {1.5, 3.0, 10.0})
    EXPECT_NEAR(irradiance(*lights[0], {0, float(1 + d), 0}, {0, -1, 0}), kPi * L * r * r / (d * d),
                1e-3 * kPi * L * r * r / (d * d));
}

}  // namespace
}  // namespace darc
