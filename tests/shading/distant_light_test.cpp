// A distant light with an angular diameter (distantlight's "angle"; PxrDistantLight's
// angleExtent): sampled uniformly over the cone it subtends, each sample carrying the light's
// whole irradiance, so that a surface facing it gets the delta light's value and shadows soften.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shading/lights.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

std::vector<std::unique_ptr<Light>> lights_of(const std::string& world_body) {
  test::Built b = test::build("WorldBegin\n" + world_body + "\nWorldEnd\n");
  EXPECT_EQ(b.scenes.size(), 1u);
  Diagnostics diag([](const Diagnostic&) {});
  return make_lights(b.scenes.at(0).lights, diag);
}

constexpr float kDegree = std::numbers::pi_v<float> / 180;

TEST(DistantLightAngle, ALightWithAnAngleIsSampledInsideItsCone) {
  // Toward -z, 10 degrees across: every sample within 5 degrees of the axis, and the mean of
  // Cl (N . L) facing it is the light's intensity times the mean cosine over the cone,
  // (1 + cos 5 degrees) / 2.
  const auto lights = lights_of(
      "LightSource \"distantlight\" 1 \"intensity\" [2] \"from\" [0 0 0] \"to\" [0 0 -1] \"float angle\" [10] "
      "\"float nsamples\" [8]");
  ASSERT_EQ(lights.size(), 1u);
  ASSERT_EQ(lights[0]->samples(), 8);
  const Vec3f axis{0, 0, 1};  // toward the light
  double sum = 0;
  float widest = 0;
  constexpr int kSide = 64;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      LightContribution c;
      ASSERT_TRUE(lights[0]->sample({1, 2, 3}, (i + 0.5f) / kSide, (j + 0.5f) / kSide, c));
      EXPECT_TRUE(std::isinf(c.distance));
      widest = std::max(widest, std::acos(std::min(1.0f, dot(c.L, axis))));
      sum += c.Cl.x * dot(c.L, axis);
    }
  EXPECT_LE(widest, 5 * kDegree + 1e-4f);
  EXPECT_GE(widest, 4.9f * kDegree) << "the samples reach the cone's edge";
  EXPECT_NEAR(sum / (kSide * kSide), 2 * (1 + std::cos(5 * kDegree)) / 2, 1e-4);
}

TEST(DistantLightAngle, WithoutAnAngleItIsADeltaLight) {
  const auto lights = lights_of("LightSource \"distantlight\" 1 \"from\" [0 0 0] \"to\" [0 0 -1]");
  ASSERT_EQ(lights.size(), 1u);
  EXPECT_EQ(lights[0]->samples(), 0);
  LightContribution c;
  ASSERT_TRUE(lights[0]->illuminate({0, 0, 0}, c));
  EXPECT_EQ(c.L, (Vec3f{0, 0, 1}));
}

TEST(DistantLightAngle, PxrDistantLightTakesItsAngleExtentAndRenderMansDefault) {
  // RenderMan's default angleExtent is the sun's 0.53 degrees: sampled (16 samples unless
  // fixedSampleCount says otherwise); angleExtent 0 is a delta light.
  const auto sun = lights_of("Light \"PxrDistantLight\" \"sun\"");
  ASSERT_EQ(sun.size(), 1u);
  EXPECT_EQ(sun[0]->samples(), 16);
  const auto eight = lights_of("Light \"PxrDistantLight\" \"sun\" \"float angleExtent\" [20] \"int fixedSampleCount\" [8]");
  ASSERT_EQ(eight.size(), 1u);
  EXPECT_EQ(eight[0]->samples(), 8);
  const auto hard = lights_of("Light \"PxrDistantLight\" \"sun\" \"float angleExtent\" [0]");
  ASSERT_EQ(hard.size(), 1u);
  EXPECT_EQ(hard[0]->samples(), 0);
}

}  // namespace
}  // namespace darc
