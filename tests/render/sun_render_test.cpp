// A distant light with an angular diameter (a sun) rendered end to end with the default hider and
// the stochastic one: the soft shadow of a sphere against the analytic share of the light's
// irradiance that the sphere leaves, and the hard shadow of the same light without an angle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "support/render.h"

namespace darc {
namespace {

using test::render_image;

constexpr int kSize = 9;

// A matte floor lit from straight above by a distant light `angle` degrees across, seen from 45
// degrees above with a narrow lens (the centre pixel sees the floor's point under the sphere,
// past it); a sphere of radius 0.25 at height 1 over that point when `sphere`.
std::string sun_scene(float angle, bool sphere, float radius = 0.25f) {
  std::ostringstream s;
  s << "Format " << kSize << " " << kSize << " 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [1]\nTranslate 0 0 5.657\nRotate -45 1 0 0\nWorldBegin\n"
    << "LightSource \"distantlight\" 1 \"intensity\" [1] \"from\" [0 10 0] \"to\" [0 0 0] \"float angle\" [" << angle
    << "] \"int nsamples\" [4096] \"string shadowname\" [\"raytrace\"]\n"
    << "Surface \"matte\" \"Kd\" [1]\nPolygon \"P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n";
  if (sphere)
    s << "TransformBegin\nTranslate 0 1 0\nSphere " << radius << " " << -radius << " " << radius << " 360\nTransformEnd\n";
  s << "WorldEnd\n";
  return s.str();
}

float centre(const Image& image) { return image.at(kSize / 2, kSize / 2, 0); }

TEST(SunRender, ASphereUnderASunLeavesTheAnalyticShareOfItsIrradiance) {
  // Directions uniform in the sun's cone of half-angle a, each weighted by its cosine on the
  // floor: the sphere (half-angle b, sin b = R / c) takes sin^2 b / sin^2 a of the irradiance.
  // a = 30 degrees, R / c = 0.25: 0.75 is left.
  const double expected = 1 - 0.25 * 0.25 / 0.25;
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const float open = centre(render_image(sun_scene(60, false), hider));
    const float shaded = centre(render_image(sun_scene(60, true), hider));
    EXPECT_GT(open, 0.5f) << to_string(hider);
    EXPECT_NEAR(shaded / open, expected, 0.03 * expected) << to_string(hider);
    // Without an angle the same point lies in the sphere's hard shadow.
    EXPECT_LT(centre(render_image(sun_scene(0, true), hider)), 0.01f) << to_string(hider);
  }
}

TEST(SunRender, ASmallSunIsOneConeShadowRayInTheDistanceHider) {
  // An 8-degree sun (half-angle a = 4 degrees, within kMaxConeShadowHalfAngle) over a sphere of
  // R / c = 0.05: 1 - (0.05 / sin a)^2 = 0.486 of the irradiance is left. The distance hider
  // traces one shadow ray per shading point, its footprint widened by the cone (the sphere's
  // coverage of it from the 8x8 sub-rays: a few percent), the stochastic hider the light's samples.
  const double sin_a = std::sin(4 * std::numbers::pi / 180);
  const double expected = 1 - (0.05 / sin_a) * (0.05 / sin_a);
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const test::RenderedFrame open = test::render_rib(sun_scene(8, false), test::single_thread(hider));
    const test::RenderedFrame shaded = test::render_rib(sun_scene(8, true, 0.05f), test::single_thread(hider));
    EXPECT_NEAR(centre(shaded.image) / centre(open.image), expected, 0.05 * expected) << to_string(hider);
    const RayCounters& c = shaded.stats.counters;
    const uint64_t shadow_rays = c.traced_by_kind[int(SecondaryKind::Shadow)] + c.pruned_by_kind[int(SecondaryKind::Shadow)];
    if (hider == HiderKind::Distance)
      EXPECT_EQ(shadow_rays, c.primary_rays) << "one cone shadow ray per pixel";
    else
      EXPECT_GE(shadow_rays, 4096 * c.primary_rays) << "the light's samples";
  }
}

}  // namespace
}  // namespace darc
