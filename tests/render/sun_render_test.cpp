// A distant light with an angular diameter (a sun) rendered end to end with the default hider and
// the stochastic one: the soft shadow of a sphere against the analytic share of the light's
// irradiance that the sphere leaves, and the hard shadow of the same light without an angle.
#include <gtest/gtest.h>

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
std::string sun_scene(float angle, bool sphere) {
  std::ostringstream s;
  s << "Format " << kSize << " " << kSize << " 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [1]\nTranslate 0 0 5.657\nRotate -45 1 0 0\nWorldBegin\n"
    << "LightSource \"distantlight\" 1 \"intensity\" [1] \"from\" [0 10 0] \"to\" [0 0 0] \"float angle\" [" << angle
    << "] \"int nsamples\" [4096] \"string shadowname\" [\"raytrace\"]\n"
    << "Surface \"matte\" \"Kd\" [1]\nPolygon \"P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n";
  if (sphere) s << "TransformBegin\nTranslate 0 1 0\nSphere 0.25 -0.25 0.25 360\nTransformEnd\n";
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

}  // namespace
}  // namespace darc
