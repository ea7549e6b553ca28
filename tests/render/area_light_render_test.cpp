// Area lights rendered end to end, with the default hider and the stochastic one: the soft shadow
// of a sphere under a disc light against the analytic visible fraction of the light's
// irradiance (lookdev.md §2.4, reference 5), and the light's samples the same for any thread
// count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

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

}  // namespace
}  // namespace darc
