// Area lights against analytic irradiance (lookdev.md §2.4): each sample's Cl is the light's
// radiance times the solid angle it stands for over pi, so pi times the mean of Cl cos over the
// samples is the irradiance.
#include "shading/area_lights.h"
#include "shading/lights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace darc {
namespace {

constexpr double kPi = std::numbers::pi;

// A light whose own x, y, z axes go to the rows' vectors, its origin to `at`.
Matrix4 frame(Vec3d x, Vec3d y, Vec3d z, Vec3d at) {
  const double v[16] = {x.x, x.y, x.z, 0, y.x, y.y, y.z, 0, z.x, z.y, z.z, 0, at.x, at.y, at.z, 1};
  return Matrix4::from_row_major(v);
}

// The irradiance at P on a surface of normal N, over a rows x cols grid of the light's
// parameters (the stratum centres, no rotation).
double irradiance(const Light& light, const Vec3f& P, const Vec3f& N, int side = 64) {
  double sum = 0;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      LightContribution lc;
      if (!light.sample(P, (i + 0.5f) / side, (j + 0.5f) / side, lc)) continue;
      sum += lc.Cl.x * std::max(0.0f, dot(N, lc.L));
    }
  return kPi * sum / (side * side);
}

TEST(AreaLights, DiskOnItsAxis) {
  // Radius a at height h facing the receiver: E = pi L a^2 / (a^2 + h^2).
  const double a = 1, h = 2;
  auto light = make_area_light(AreaShape::Disk, frame({2 * a, 0, 0}, {0, 0, 2 * a}, {0, -1, 0}, {0, h, 0}),
                               {1.5f, 1.5f, 1.5f}, 16);
  EXPECT_EQ(light->samples(), 16);
  EXPECT_NEAR(irradiance(*light, {0, 0, 0}, {0, 1, 0}), kPi * 1.5 * a * a / (a * a + h * h), 2e-3);
}

TEST(AreaLights, RectangleWithACornerAboveTheReceiver) {
  // Sides a, b parallel to the receiver at height h, a corner straight above it (X = a / h,
  // Y = b / h): E = L / 2 [X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2)) + Y / sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))].
  const double a = 1, b = 2, h = 1;
  auto light = make_area_light(AreaShape::Rect, frame({a, 0, 0}, {0, 0, b}, {0, -1, 0}, {a / 2, h, b / 2}),
                               {1, 1, 1}, 16);
  const double X = a / h, Y = b / h;
  const double expected = 0.5 * (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
                                 Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y)));
  EXPECT_NEAR(irradiance(*light, {0, 0, 0}, {0, 1, 0}, 128), expected, 2e-3 * expected);
}

// Irradiance from a rectangle of sides a, b parallel to the receiver at height h, with a corner
// straight above it.
double corner_irradiance(double a, double b, double h) {
  const double X = a / h, Y = b / h;
  return 0.5 * (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
                Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y)));
}

TEST(AreaLights, RectangleJustAboveTheReceiverIsSampledBySolidAngle) {
  // A 2 x 2 light 0.05 above the receiver's point, centred over it: seen from there it fills
  // most of the hemisphere. Sampled by area, 16 strata would weigh the four near the middle by
  // area cos^2 / d^2 and miss the peak under the point (0.17 against 3.1); sampled by solid
  // angle each stands for a sixteenth of it and only the receiver's cosine varies.
  const double h = 0.05;
  auto light = make_area_light(AreaShape::Rect, frame({2, 0, 0}, {0, 0, 2}, {0, -1, 0}, {0, h, 0}), {1, 1, 1}, 16);
  const double exact = 4 * corner_irradiance(1, 1, h);
  // Measured: 6 % high at 4 x 4 strata, 1.9 % at 8 x 8, 0.06 % at 64 x 64 (by area, 4 x 4: -95 %).
  EXPECT_NEAR(irradiance(*light, {0, 0, 0}, {0, 1, 0}, 4), exact, 0.08 * exact);
  EXPECT_NEAR(irradiance(*light, {0, 0, 0}, {0, 1, 0}, 8), exact, 0.03 * exact);
  EXPECT_NEAR(irradiance(*light, {0, 0, 0}, {0, 1, 0}, 64), exact, 1e-3 * exact);
  // Off centre, near an edge (x = 0.9, so the light extends 0.1 one way and 1.9 the other).
  const double off = corner_irradiance(0.1, 1, h) * 2 + corner_irradiance(1.9, 1, h) * 2;
  EXPECT_NEAR(irradiance(*light, {0.9f, 0, 0}, {0, 1, 0}, 64), off, 2e-3 * off);
  // Every sample stands for the same solid angle and lands on the rectangle.
  float first = -1;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      LightContribution lc;
      ASSERT_TRUE(light->sample({0.9f, 0, 0}, (i + 0.5f) / 8, (j + 0.5f) / 8, lc));
      if (first < 0) first = lc.Cl.x;
      EXPECT_FLOAT_EQ(lc.Cl.x, first);
      const Vec3f X = Vec3f{0.9f, 0, 0} + lc.L * lc.distance;
      EXPECT_NEAR(X.y, h, 1e-5);
      EXPECT_LE(std::abs(X.x), 1 + 1e-5);
      EXPECT_LE(std::abs(X.z), 1 + 1e-5);
    }
}

TEST(AreaLights, ShearedRectangleIsSampledByArea) {
  // Under a shear the light is a parallelogram: sampled by area, its irradiance still exact. Its
  // vertical projection is the parallelogram (0,0), (1,0), (1.5,1), (0.5,1) at height 1 over the
  // receiver at the origin, whose irradiance is the polygon's (Lambert's formula).
  auto light = make_area_light(AreaShape::Rect, frame({1, 0, 0}, {0.5, 0, 1}, {0, -1, 0}, {0.75, 1, 0.5}),
                               {1, 1, 1}, 16);
  const Vec3d corners[4] = {{0, 1, 0}, {1, 1, 0}, {1.5, 1, 1}, {0.5, 1, 1}};
  double expected = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3d p = normalize(corners[i]), q = normalize(corners[(i + 1) % 4]);
    const Vec3d c = cross(p, q);
    expected += std::acos(std::clamp(dot(p, q), -1.0, 1.0)) * c.y / length(c);
  }
  expected = 0.5 * std::abs(expected);
  EXPECT_NEAR(irradiance(*light, {0, 0, 0}, {0, 1, 0}, 128), expected, 2e-3 * expected);
}

TEST(AreaLights, SphereSeenFromOutside) {
  // Radius R at distance D, the receiver facing its centre: E = pi L R^2 / D^2, wherever the
  // cone's samples land.
  const double R = 0.75, D = 3;
  auto light = make_area_light(AreaShape::Sphere, frame({2 * R, 0, 0}, {0, 2 * R, 0}, {0, 0, 2 * R}, {0, D, 0}),
                               {2, 2, 2}, 16);
  EXPECT_NEAR(irradiance(*light, {0, 0, 0}, {0, 1, 0}), kPi * 2 * R * R / (D * D), 1e-3);
  // The samples end on the sphere's near side.
  LightContribution lc;
  ASSERT_TRUE(light->sample({0, 0, 0}, 0.0f, 0.3f, lc));
  EXPECT_NEAR(lc.distance, D - R, 1e-4);
  EXPECT_FALSE(light->sample({0, float(D), 0.1f}, 0.5f, 0.5f, lc)) << "inside the light: nothing";
}

TEST(AreaLights, FlatLightsLightOneSide) {
  // PxrRectLight and PxrDiskLight emit toward their own +z (lookdev.md §2.2).
  auto rect = make_area_light(AreaShape::Rect, frame({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}), {1, 1, 1}, 4);
  LightContribution lc;
  EXPECT_TRUE(rect->sample({0, 0, 2}, 0.3f, 0.6f, lc));
  EXPECT_GT(lc.Cl.x, 0.0f);
  EXPECT_FALSE(rect->sample({0, 0, -2}, 0.3f, 0.6f, lc));
  // A mirrored frame keeps the side its own +z points to.
  auto mirrored = make_area_light(AreaShape::Disk, frame({-1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}), {1, 1, 1}, 4);
  EXPECT_TRUE(mirrored->sample({0, 0, 2}, 0.3f, 0.6f, lc));
  EXPECT_FALSE(mirrored->sample({0, 0, -2}, 0.3f, 0.6f, lc));
}

TEST(AreaLights, SixteenStrataAreCloseAlready) {
  const double a = 1, h = 1.5;
  auto light = make_area_light(AreaShape::Disk, frame({2 * a, 0, 0}, {0, 0, 2 * a}, {0, -1, 0}, {0, h, 0}),
                               {1, 1, 1}, 16);
  const double exact = kPi * a * a / (a * a + h * h);
  EXPECT_NEAR(irradiance(*light, {0.3f, 0, 0.2f}, {0, 1, 0}, 4), exact * 1.0, 0.05 * exact);
}

TEST(AreaLights, MadeFromTheirLightShaderNames) {
  Diagnostics diag([](const Diagnostic&) { ADD_FAILURE() << "no warning expected"; });
  ParamList p;
  Param n;
  n.name = "nsamples";
  n.decl.type = ParamType::Integer;
  n.floats = {9};
  p.params.push_back(n);
  const Matrix4 down = frame({1, 0, 0}, {0, 0, 1}, {0, -1, 0}, {0, 2, 0});
  auto lights = make_lights({LightDesc{"rectlight", p, down, {}, true}, LightDesc{"disklight", {}, down, {}, false},
                             LightDesc{"spherelight", {}, down, {}, false}},
                            diag);
  ASSERT_EQ(lights.size(), 3u);
  EXPECT_EQ(lights[0]->samples(), 9);
  EXPECT_TRUE(lights[0]->casts_shadows());
  EXPECT_EQ(lights[1]->samples(), kDefaultAreaLightSamples);
  EXPECT_GT(irradiance(*lights[2], {0, 0, 0}, {0, 1, 0}), 0.0);
}

}  // namespace
}  // namespace darc
