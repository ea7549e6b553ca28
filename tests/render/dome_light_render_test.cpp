// The dome light rendered end to end with the default hider and the stochastic one, against the
// analytic values of lookdev.md §2.4: a white diffuse sphere under a dome of radiance 1 reflects
// radiance 1 over its whole disc (RenderMan's physically based convention), a non-absorbing hair
// fibre reflects 1 (the fibre's white furnace, rendered), and a white plane beside a black sphere
// resting on it keeps the unoccluded share 1 - R^3 / (d^2 + R^2)^1.5 of the dome's irradiance.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "support/render.h"

namespace darc {
namespace {

using test::ortho_view;
using test::render_image;

// RenderMan's convention: a PxrDiffuse of diffuseColor 1 under a PxrDomeLight of intensity 1 has
// radiance 1. The samples follow the cosine about the normal, so an unshadowed sample of a
// diffuse surface weighs exactly 1: any deviation is a bias (a self-shadowed sample, a missed pi).
TEST(DomeLightRender, AWhiteDiffuseSphereUnderAUnitDomeHasRadianceOneOverItsWholeDisc) {
  constexpr int kSize = 15;
  std::ostringstream s;
  s << ortho_view(kSize, 1.1) << "WorldBegin\n"
    << "Light \"PxrDomeLight\" \"dome\" \"float intensity\" [1] \"int fixedSampleCount\" [64]\n"
    << "Bxdf \"PxrDiffuse\" \"white\" \"color diffuseColor\" [1 1 1]\nSphere 1 -1 1 360\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image image = render_image(s.str(), hider);
    int covered = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (image.at(x, y, 3) < 1.0f) continue;  // the silhouette's pixels are partly sphere
        ++covered;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(image.at(x, y, c), 1.0f, 0.02f) << to_string(hider) << " pixel " << x << "," << y;
      }
    EXPECT_GT(covered, kSize * kSize / 2) << to_string(hider);
  }
}

// A horizontal strand of Chiang hair under the dome: with sigma_a 0 the fibre loses no energy, so
// what it scatters toward the camera integrates the dome's radiance 1; absorption darkens it. A
// dome without a map leaves every sample to the fibre's lobes (integrator/secondary_rays.cpp): a
// clear fibre's samples each weigh the dome's radiance, and narrow lobes converge as fast as rough
// ones. (Sampling the dome uniformly over the sphere, beta 0.3 still scattered by 10 % at 4096.)
float hair_under_dome(const std::string& absorption, HiderKind hider, float beta = 0.7f, int samples = 256) {
  constexpr int kSize = 9;
  std::ostringstream s;
  s << ortho_view(kSize, 1) << "WorldBegin\n"
    << "LightSource \"domelight\" 1 \"intensity\" [1] \"int nsamples\" [" << samples << "]\n"
    << "Surface \"chianghair\" \"color sigma_a\" [" << absorption << "] \"float beta_m\" [" << beta
    << "] \"float beta_n\" [" << beta << "]\n"
    << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [-2 0 0  2 0 0] \"constantwidth\" [1]\nWorldEnd\n";
  const Image image = render_image(s.str(), hider);
  EXPECT_EQ(image.at(kSize / 2, kSize / 2, 3), 1.0f);
  return image.at(kSize / 2, kSize / 2, 0);
}

TEST(DomeLightRender, ANonAbsorbingHairFibreUnderAUnitDomeReflectsOne) {
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    for (float beta : {0.15f, 0.3f, 0.7f})
      EXPECT_NEAR(hair_under_dome("0 0 0", hider, beta), 1.0f, 0.05f) << to_string(hider) << " beta " << beta;
    // 32 samples (16 from each): within 5 % at beta 0.3.
    EXPECT_NEAR(hair_under_dome("0 0 0", hider, 0.3f, 32), 1.0f, 0.05f) << to_string(hider);
    const float white = hair_under_dome("0 0 0", hider);
    const float absorbing = hair_under_dome("0.5 0.5 0.5", hider);
    EXPECT_LT(absorbing, 0.8f * white) << to_string(hider);
    EXPECT_GT(absorbing, 0.0f) << to_string(hider);
  }
}

// Seen from above: a white matte plane y = 0 and a black sphere of radius 1 resting on it at the
// origin. A dome over the upper hemisphere lights a point of the plane at distance d from the
// contact point by the share 1 - R^3 / (d^2 + R^2)^1.5 of its irradiance (the sphere's cap touches
// the horizon). The pixels are 0.125 wide, centred on x = -4 + 0.125 i, z = -4 + 0.125 j (the
// stochastic hider's sample lies anywhere in its pixel: a wider pixel moved it off d by more
// than the tolerance near the sphere).
TEST(DomeLightRender, ADomeCastsTheAnalyticShadowOfASphereOnAPlane) {
  constexpr int kSize = 65;
  std::ostringstream s;
  s << ortho_view(kSize, 4.0625) << "Rotate -90 1 0 0\nWorldBegin\n"
    << "LightSource \"domelight\" 1 \"intensity\" [1] \"int nsamples\" [1024] \"string shadowname\" [\"raytrace\"]\n"
    << "AttributeBegin\nSurface \"matte\" \"Kd\" [1]\nPolygon \"P\" [-20 0 -20  -20 0 20  20 0 20  20 0 -20]\nAttributeEnd\n"
    << "AttributeBegin\nSurface \"constant\"\nColor 0 0 0\nTranslate 0 1 0\nSphere 1 -1 1 360\nAttributeEnd\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image image = render_image(s.str(), hider);
    // The plane far from the sphere sees the whole dome.
    EXPECT_NEAR(image.at(0, 0, 0), 1.0f, 0.01f) << to_string(hider);
    for (int i : {44, 48, 56}) {  // d = 1.5, 2, 3 along +x; the same along -z
      const double d = -4 + 0.125 * i;
      const double expected = 1 - 1 / std::pow(d * d + 1, 1.5);
      EXPECT_NEAR(image.at(i, kSize / 2, 0), expected, 0.03 * expected) << to_string(hider) << " d = " << d;
      EXPECT_NEAR(image.at(kSize / 2, kSize - 1 - i, 0), expected, 0.03 * expected) << to_string(hider) << " d = " << d;
    }
  }
}

}  // namespace
}  // namespace darc
