// Area lights rendered end to end, with the default hider and the stochastic one: the soft shadow
// of a sphere under a disc light against the analytic visible fraction of the light's
// irradiance (lookdev.md §2.4, reference 5), and the light's samples the same for any thread
// count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "shading/chiang_hair.h"
#include "support/render.h"

namespace darc {
namespace {

using test::render_image;

constexpr int kSize = 9;

// A matte floor under a disc light of radius a = 2 at height 3 facing down, seen from 45 degrees
// above (past the sphere, when there is one) with a narrow lens: the centre pixel sees the
// floor's point under the light's axis.
std::string disc_light_scene(bool sphere, int samples) {
  std::ostringstream s;
  s << "Format " << kSize << " " << kSize << " 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [1]\nTranslate 0 0 5.657\nRotate -45 1 0 0\nWorldBegin\n"
    << "TransformBegin\nConcatTransform [4 0 0 0  0 0 4 0  0 -1 0 0  0 3 0 1]\n"
    << "LightSource \"disklight\" 1 \"intensity\" [1] \"int nsamples\" [" << samples
    << "] \"string shadowname\" [\"raytrace\"]\nTransformEnd\n"
    << "Surface \"matte\" \"Kd\" [1]\nPolygon \"P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n";
  if (sphere) s << "TransformBegin\nTranslate 0 1 0\nSphere 0.5 -0.5 0.5 360\nTransformEnd\n";
  s << "WorldEnd\n";
  return s.str();
}

float centre(const Image& image) { return image.at(kSize / 2, kSize / 2, 0); }

TEST(AreaLightRender, SphereUnderADiscLightLeavesTheAnalyticShareOfItsIrradiance) {
  // Disc radius a at height h over the receiver, sphere radius R centred on the axis at height c:
  // the receiver keeps 1 - (R / c)^2 (a^2 + h^2) / a^2 of its irradiance (valid while the sphere's
  // cone lies inside the light's: here 0.1875).
  const double a = 2, h = 3, R = 0.5, c = 1;
  const double expected = 1 - (R / c) * (R / c) * (a * a + h * h) / (a * a);
  // 4096 samples: the shadow's edge on the light cuts through strata, and 1024 left 5 % of noise.
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const float open = centre(render_image(disc_light_scene(false, 4096), hider));
    const float shaded = centre(render_image(disc_light_scene(true, 4096), hider));
    // The open floor: E / pi = a^2 / (a^2 + h^2) for radiance 1 and Kd 1.
    EXPECT_NEAR(open, a * a / (a * a + h * h), 0.01 * a * a / (a * a + h * h)) << to_string(hider);
    EXPECT_NEAR(shaded / open, expected, 0.03 * expected) << to_string(hider);
  }
}

// The floor under an RI AreaLightSource whose geometry is a square of side 2 at height 3 (its
// corners in the order given), switched on again after its block by Illuminate.
std::string quad_area_light_scene(const std::string& corners) {
  std::ostringstream s;
  s << "Format " << kSize << " " << kSize << " 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [1]\nTranslate 0 0 5.657\nRotate -45 1 0 0\nWorldBegin\n"
    << "AttributeBegin\nAreaLightSource \"arealight\" 7 \"intensity\" [2] \"int nsamples\" [1024]\n"
    << "Polygon \"P\" [" << corners << "]\nAttributeEnd\nIlluminate 7 1\n"
    << "Surface \"matte\" \"Kd\" [1]\nPolygon \"P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\nWorldEnd\n";
  return s.str();
}

TEST(AreaLightRender, AnAreaLightSourcesGeometryLightsFromTheSideItsNormalFaces) {
  // A square of side 2a at height h, centred above the receiver: four times the corner formula
  // (sides a, a), E = 4 L X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2)) with X = a / h; the matte
  // floor of Kd 1 shows E / pi.
  const double a = 1, h = 3, L = 2, X = a / h;
  const double expected = 4 * L * (X / std::sqrt(1 + X * X) * std::atan(X / std::sqrt(1 + X * X))) / std::numbers::pi;
  const float one = centre(render_image(quad_area_light_scene("-1 3 -1  1 3 -1  1 3 1  -1 3 1"), HiderKind::Distance));
  const float other = centre(render_image(quad_area_light_scene("-1 3 -1  -1 3 1  1 3 1  1 3 -1"), HiderKind::Distance));
  // One winding faces the floor, the other faces away: one-sided, as arealight's illuminate(P, N, PI/2).
  EXPECT_EQ(std::min(one, other), 0.0f);
  EXPECT_NEAR(std::max(one, other), expected, 0.01 * expected);
}

TEST(AreaLightRender, TheSameImageForAnyThreadCount) {
  const std::string rib = disc_light_scene(true, 16);
  const Image one = render_image(rib, HiderKind::Distance, 1), two = render_image(rib, HiderKind::Distance, 2);
  EXPECT_EQ(one.pixels, two.pixels);
  // Neighbouring points see the light through different strata: the penumbra is not a copy of
  // the same 16 points everywhere, so the image is not constant across the shadow.
  float lo = 1e9f, hi = -1e9f;
  for (int x = 0; x < kSize; ++x) {
    lo = std::min(lo, one.at(x, kSize / 2, 0));
    hi = std::max(hi, one.at(x, kSize / 2, 0));
  }
  EXPECT_GT(hi, lo);
}

// A mat of thin strands (400, 0.012 wide, random directions) half a unit over a matte floor,
// under a rect light 1.5 wide at height 3, seen from above: the floor is in the strands' soft
// shadows. With `samples` light samples per shading point.
std::string hair_mat_scene(int samples) {
  std::ostringstream s;
  s.precision(6);
  s << "Format 40 40 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\nProjection \"perspective\" \"fov\" [30]\n"
    << "Translate 0 0 6\nRotate -90 1 0 0\nWorldBegin\nTransformBegin\nTranslate 0 3 0\nRotate 90 1 0 0\n"
    << "Scale 1.5 1.5 1.5\nLightSource \"rectlight\" 1 \"intensity\" [4] \"int nsamples\" [" << samples
    << "] \"string shadowname\" [\"raytrace\"]\nTransformEnd\nSurface \"matte\" \"Kd\" [1]\n"
    << "Polygon \"P\" [-3 0 -3  3 0 -3  3 0 3  -3 0 3]\nCurves \"linear\" [";
  constexpr int kStrands = 400;
  for (int i = 0; i < kStrands; ++i) s << "2 ";
  s << "] \"nonperiodic\" \"P\" [";
  uint32_t state = 7;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1 << 24);
  };
  for (int i = 0; i < kStrands; ++i) {
    const double x = 3 * next() - 1.5, z = 3 * next() - 1.5, a = 3.14159 * next(), l = 0.5 + 0.7 * next();
    const double y = 0.4 + 0.4 * next(), dx = std::cos(a) * l / 2, dz = std::sin(a) * l / 2;
    s << x - dx << " " << y << " " << z - dz << "  " << x + dx << " " << y << " " << z + dz << "  ";
  }
  s << "] \"constantwidth\" [0.012]\nWorldEnd\n";
  return s.str();
}

double rms_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) sum += std::pow(double(a.at(x, y, c)) - double(b.at(x, y, c)), 2);
  return std::sqrt(sum / (3.0 * a.width * a.height));
}

// The distance hider's cone shadow ray toward a light with extent (issue 19, item 3): one shadow
// ray per shading point whose footprint grows from the receiving patch to the light, its
// transmittance the A-buffer's over that cone. Against the same hider with 256 point-sampled
// shadow rays per shading point (the unoccluded light sampled alike), the soft shadows of a mat
// of strands come out closer than with 4 point-sampled rays, from one shadow ray per shading
// point. Measured: RMSE 0.0069 for the cone, 0.0129 with 4 rays (40x40, one thread; 4 rays gave
// 0.0179 before the rect light was sampled by solid angle).
TEST(AreaLightRender, OneConeShadowRayGivesTheSoftShadowOfStrands) {
  RenderOptions sampled = test::single_thread(HiderKind::Distance);
  sampled.distance.area_light_cones = false;
  const Image reference = test::render_rib(hair_mat_scene(256), sampled).image;
  const Image four = test::render_rib(hair_mat_scene(4), sampled).image;
  const test::RenderedFrame cone = test::render_rib(hair_mat_scene(256), test::single_thread(HiderKind::Distance));
  const double cone_error = rms_difference(cone.image, reference), four_error = rms_difference(four, reference);
  std::printf("soft shadows of strands, RMSE against 256 point-sampled shadow rays: cone %.4f, 4 rays %.4f\n",
              cone_error, four_error);
  EXPECT_LT(cone_error, 0.6 * four_error) << "cone " << cone_error << ", 4 rays " << four_error;
  const RayCounters& c = cone.stats.counters;
  const uint64_t shadow_rays = c.traced_by_kind[int(SecondaryKind::Shadow)] + c.pruned_by_kind[int(SecondaryKind::Shadow)];
  EXPECT_LT(shadow_rays, 4 * c.fragments) << "about one shadow ray per shaded fragment, not 256";
}

}  // namespace
}  // namespace darc

namespace darc {
namespace {

// A horizontal chianghair strand (along x, seen along +z) with a 4x2 rect light behind it (z = 1,
// facing the camera), the other side of the strand from the camera: the fibre's TT lobe carries
// the light through. (The lobe looks straight through: a point 0.05 inside an edge of the light
// along the fibre gets half as much, so the light reaches past the image's sides, where the
// stochastic hider's points move within their pixels.) At beta 0.1 and 64 samples the light's
// strata (0.22 rad) are wider than 1.4 lobe widths (0.08 rad), so half the samples are drawn from the fibre's lobes and both halves
// weighed by MIS (integrator/secondary_rays.cpp). Each pixel's light must be the integral of the
// fibre's S across its width over the rectangle, computed here over the light's area: a wrong
// density in the weights (the spherical rectangle's 1 / solid angle, a lobe's pdf) biases it (by
// area instead of by solid angle: +11 %). With shadows on, the distance hider's one cone shadow
// ray sees nothing between, so the same.
TEST(AreaLightRender, AHairStrandUnderARectLightGetsTheFibresIntegralOverTheRectangle) {
  ChiangHairParams params;
  params.sigma_a = {0.2f, 0.2f, 0.2f};
  params.beta_m = params.beta_n = 0.1f;
  const ChiangHair hair(params);
  const Vec3f T{1, 0, 0}, wo{0, 0, -1};
  // The three middle rows are wholly strand: pixel centres at x, y = -1 + (i + 0.5) 2 / 9, z = 0.
  constexpr int kGridX = 160, kGridY = 80, kRows[] = {3, 4, 5};
  double expected = 0;
  for (int j : kRows)
    for (int i = 0; i < kSize; ++i) {
      const Vec3f P{-1 + (float(i) + 0.5f) * 2 / kSize, 1 - (float(j) + 0.5f) * 2 / kSize, 0};
      double sum = 0;
      for (int a = 0; a < kGridX; ++a)
        for (int b = 0; b < kGridY; ++b) {
          const Vec3f X{-2 + (float(a) + 0.5f) * 4 / kGridX, -1 + (float(b) + 0.5f) * 2 / kGridY, 1};
          const Vec3f d = X - P;
          const float d2 = length_squared(d);
          const Vec3f wi = d / std::sqrt(d2);
          // dw = cos_l dA / d^2, cos_l = wi.z (the light faces -z), dA = (4 / kGridX) (2 / kGridY).
          sum += hair.scattering_across(T, wo, wi).x * wi.z / d2 * (8.0 / (kGridX * kGridY));
        }
      expected += sum / (3 * kSize);
    }
  ASSERT_GT(expected, 0.1) << "the rectangle lies in the fibre's forward lobe";
  for (const std::string shadows : {"", "\"string shadowname\" [\"raytrace\"] "}) {
    std::ostringstream s;
    s << "Format " << kSize << " " << kSize << " 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
      << "Projection \"orthographic\"\nScreenWindow -1 1 -1 1\nTranslate 0 0 10\nWorldBegin\n"
      << "AttributeBegin\nTranslate 0 0 1\nRotate 180 0 1 0\nScale 4 2 1\n"
      << "LightSource \"rectlight\" 1 \"intensity\" [1] " << shadows << "\"int nsamples\" [64]\nAttributeEnd\n"
      << "Illuminate 1 1\n"
      << "Surface \"chianghair\" \"color sigma_a\" [0.2 0.2 0.2] \"float beta_m\" [0.1] \"float beta_n\" [0.1]\n"
      << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [-2 0 0  2 0 0] \"constantwidth\" [1]\nWorldEnd\n";
    for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
      const Image image = render_image(s.str(), hider);
      double mean = 0;
      for (int j : kRows)
        for (int x = 0; x < kSize; ++x) {
          ASSERT_EQ(image.at(x, j, 3), 1.0f) << to_string(hider) << " " << x << "," << j;
          mean += image.at(x, j, 0) / (3 * kSize);
        }
      // 27 points, each scattering by about 8 % at 64 samples.
      EXPECT_NEAR(mean, expected, 0.04 * expected) << to_string(hider) << " shadows: " << shadows;
    }
  }
}

}  // namespace
}  // namespace darc
