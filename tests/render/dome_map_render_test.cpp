// The dome's lat-long map rendered end to end, both hiders, against analytic values: a white
// diffuse sphere under a dome bright over its upper hemisphere has radiance (1 + n_z) / 2, the
// map's columns light the sides RenderMan's convention puts them on (lookdev.md §2.2), mirror
// reflections that leave the scene see the map (and a constant dome), camera rays do not, and a
// map that cannot be found is a warning at its line with the dome keeping its colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>

#include "shading/chiang_hair.h"
#include "support/darc_command.h"
#include "support/render.h"
#include "support/scenes_from_rib.h"
#include "support/texture_files.h"

namespace darc {
namespace {

using test::ortho_view;
using test::render_image;
using test::ScratchDir;

// A lat-long map of 64 x 32 texels whose texel at (s, t) (texel centres) is rgb(s, t).
std::string write_map(const ScratchDir& dir, const std::string& name, const std::function<Vec3f(float, float)>& rgb) {
  return test::write_rgb_image(dir, name, 64, 32, rgb);
}

std::string sphere_under(const std::string& light, int pixel_samples = 1) {
  return ortho_view(15, 1.1) + "PixelSamples " + std::to_string(pixel_samples) + " " + std::to_string(pixel_samples) +
         "\nWorldBegin\n" + light +
         "Bxdf \"PxrDiffuse\" \"white\" \"color diffuseColor\" [1 1 1]\nSphere 1 -1 1 360\nWorldEnd\n";
}

TEST(DomeMapRender, AnUpperHemisphereMapLightsAWhiteSphereByOnePlusNzOverTwo) {
  ScratchDir dir("dome_map_upper");
  const std::string map = write_map(dir, "upper.exr", [](float, float t) { return t < 0.5f ? Vec3f{1, 1, 1} : Vec3f{}; });
  const std::string light =
      "Light \"PxrDomeLight\" \"dome\" \"string lightColorMap\" [\"" + map + "\"] \"int fixedSampleCount\" [256]\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    // The stochastic hider point-samples the pixel: 4 x 4 of them approach its average.
    const Image image = render_image(sphere_under(light, hider == HiderKind::Stochastic ? 4 : 1), hider);
    int covered = 0;
    double worst = 0;
    for (int y = 0; y < 15; ++y)
      for (int x = 0; x < 15; ++x) {
        if (image.at(x, y, 3) < 1.0f) continue;
        ++covered;
        // The pixel's average of (1 + n_z) / 2 over the sphere's points in it, which face the
        // camera (-z): 16 x 16 points.
        double sum = 0;
        int inside = 0;
        for (int j = 0; j < 16; ++j)
          for (int i = 0; i < 16; ++i) {
            const double px = (x + (i + 0.5) / 16) / 15 * 2.2 - 1.1, py = 1.1 - (y + (j + 0.5) / 16) / 15 * 2.2;
            const double r2 = px * px + py * py;
            if (r2 >= 1) continue;
            sum += (1 - std::sqrt(1 - r2)) / 2;
            ++inside;
          }
        const double expected = sum / std::max(inside, 1);
        worst = std::max(worst, std::abs(image.at(x, y, 1) - expected));
      }
    EXPECT_GT(covered, 100) << to_string(hider);
    EXPECT_LT(worst, 0.03) << to_string(hider);
    EXPECT_LT(image.at(7, 7, 1), 0.02f) << to_string(hider) << ": the disc's centre faces the dark half";
  }
}

TEST(DomeMapRender, TheMapsColumnsLightTheSidesRenderManPutsThemOn) {
  ScratchDir dir("dome_map_columns");
  // Bright only around s = 0.25, which is -y in the dome's space; the dome rotated 90 degrees
  // about world z puts -y of its space at world +x (x' = -y... R(90, z) maps (0,-1,0) to (1,0,0)).
  const std::string map = write_map(dir, "column.exr", [](float s, float) {
    return s > 0.2f && s < 0.3f ? Vec3f{4, 4, 4} : Vec3f{};
  });
  const std::string light = "\"string lightColorMap\" [\"" + map + "\"] \"int fixedSampleCount\" [64]\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image plain = render_image(sphere_under("Light \"PxrDomeLight\" \"dome\" " + light), hider);
    // The lune around -y reaches both poles, so the far side is not quite black: compare.
    EXPECT_GT(plain.at(7, 13, 1), 0.1f) << to_string(hider) << ": the -y side (image bottom) is lit";
    EXPECT_GT(plain.at(7, 13, 1), 5 * plain.at(7, 1, 1)) << to_string(hider) << ": more than the +y side";
    const Image turned = render_image(
        sphere_under("AttributeBegin\nRotate 90 0 0 1\nLight \"PxrDomeLight\" \"dome\" " + light + "AttributeEnd\n"),
        hider);
    EXPECT_GT(turned.at(13, 7, 1), 0.1f) << to_string(hider) << ": turned, the +x side (image right) is lit";
    EXPECT_GT(turned.at(13, 7, 1), 5 * turned.at(1, 7, 1)) << to_string(hider);
    EXPECT_GT(turned.at(13, 7, 1), 1.5f * turned.at(7, 13, 1)) << to_string(hider);
  }
}

// A mirror facing the camera reflects straight back along -z: the dome's bottom row.
std::string mirror_under(const std::string& light) {
  return ortho_view(9, 1) + "Option \"trace\" \"int maxdepth\" [2]\nWorldBegin\n" + light +
         "Surface \"mirror\" \"Kd\" [0] \"Ks\" [0] \"Kr\" [1]\nPolygon \"P\" [-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0]\n"
         "WorldEnd\n";
}

TEST(DomeMapRender, MirrorReflectionsThatLeaveTheSceneSeeTheDomeAndCameraRaysDoNot) {
  ScratchDir dir("dome_map_mirror");
  const std::string map =
      write_map(dir, "halves.exr", [](float, float t) { return t < 0.5f ? Vec3f{1, 0, 0} : Vec3f{0, 0, 0.5f}; });
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image mapped =
        render_image(mirror_under("Light \"PxrDomeLight\" \"dome\" \"string lightColorMap\" [\"" + map + "\"]\n"), hider);
    EXPECT_NEAR(mapped.at(4, 4, 0), 0.0f, 1e-4f) << to_string(hider);
    EXPECT_NEAR(mapped.at(4, 4, 2), 0.5f, 1e-3f) << to_string(hider) << ": the mirror shows the lower half";
    EXPECT_EQ(mapped.at(0, 0, 3), 0.0f) << to_string(hider) << ": the dome is not seen by the camera";
    EXPECT_EQ(mapped.at(0, 0, 2), 0.0f) << to_string(hider);
    const Image constant =
        render_image(mirror_under("LightSource \"domelight\" 1 \"intensity\" [0.25] \"lightcolor\" [1 2 4]\n"), hider);
    EXPECT_NEAR(constant.at(4, 4, 0), 0.25f, 1e-3f) << to_string(hider);
    EXPECT_NEAR(constant.at(4, 4, 2), 1.0f, 1e-3f) << to_string(hider);
  }
}

TEST(DomeMapRender, EnvlightReadsItsMapAsTheDomeDoes) {
  ScratchDir dir("dome_map_envlight");
  const std::string map = write_map(dir, "upper.exr", [](float, float t) { return t < 0.5f ? Vec3f{1, 1, 1} : Vec3f{}; });
  const Image pxr = render_image(sphere_under("Light \"PxrDomeLight\" \"dome\" \"string lightColorMap\" [\"" + map +
                                              "\"] \"int fixedSampleCount\" [16]\n"),
                                 HiderKind::Distance);
  const Image env = render_image(
      sphere_under("LightSource \"envlight\" 1 \"string mapname\" [\"" + map + "\"] \"int nsamples\" [16]\n"),
      HiderKind::Distance);
  for (int y = 0; y < 15; ++y)
    for (int x = 0; x < 15; ++x) EXPECT_EQ(pxr.at(x, y, 1), env.at(x, y, 1)) << x << "," << y;
}

// A strand of Chiang hair along x seen along +z under the map bright over +z (behind it): its
// light is the integral of the fibre's S across its width over the bright hemisphere, computed
// here by quadrature from ChiangHair itself. Under a map the dome's samples follow the texels and
// the fibre's follow its lobes; MIS weighs each by the other's density (a wrong map density in
// the weights would bias this, the constant dome's furnace would not see it).
TEST(DomeMapRender, AHairStrandUnderAHalfBrightMapGetsTheFibresIntegralOverTheBrightHalf) {
  ScratchDir dir("dome_map_hair");
  const std::string map = write_map(dir, "upper.exr", [](float, float t) { return t < 0.5f ? Vec3f{1, 1, 1} : Vec3f{}; });
  ChiangHairParams params;
  params.sigma_a = {0.2f, 0.2f, 0.2f};
  params.beta_m = params.beta_n = 0.3f;
  const ChiangHair hair(params);
  const Vec3f T{1, 0, 0}, wo{0, 0, -1};
  double expected = 0;
  constexpr int kTheta = 400, kPhi = 800;  // theta from +z, dw = sin theta dtheta dphi
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * (std::numbers::pi / 2) / kTheta;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * 2 * std::numbers::pi / kPhi;
      const Vec3f wi{float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))};
      expected += hair.scattering_across(T, wo, wi).x * std::sin(theta) * (std::numbers::pi / 2 / kTheta) *
                  (2 * std::numbers::pi / kPhi);
    }
  }
  const std::string rib = ortho_view(9, 1) + "WorldBegin\nLight \"PxrDomeLight\" \"dome\" \"string lightColorMap\" [\"" +
                          map + "\"] \"int fixedSampleCount\" [1024]\n" +
                          "Surface \"chianghair\" \"color sigma_a\" [0.2 0.2 0.2] \"float beta_m\" [0.3] \"float beta_n\" [0.3]\n"
                          "Curves \"linear\" [2] \"nonperiodic\" \"P\" [-2 0 0  2 0 0] \"constantwidth\" [1]\nWorldEnd\n";
  EXPECT_GT(expected, 0.2) << "the bright half lies behind the fibre: its TT lobe sees it";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image image = render_image(rib, hider);
    // The middle row's 9 pixels: 9 shading points whose samples are rotated independently
    // (one point's estimate at 1024 samples scatters by about 0.7 %).
    double mean = 0;
    for (int x = 0; x < 9; ++x) {
      ASSERT_EQ(image.at(x, 4, 3), 1.0f) << to_string(hider);
      mean += image.at(x, 4, 0) / 9.0;
    }
    EXPECT_NEAR(mean, expected, 0.03 * expected) << to_string(hider);
  }
}

TEST(DomeMapRender, AMissingMapIsAWarningAtItsLineAndTheDomeKeepsItsColour) {
  const std::string rib = sphere_under("Light \"PxrDomeLight\" \"dome\" \"string lightColorMap\" [\"no_such_map.exr\"]\n");
  const test::Built built = test::build(rib);
  int warnings = 0;
  for (const Diagnostic& d : built.diagnostics)
    if (d.severity == Severity::Warning && d.message.find("no_such_map.exr") != std::string::npos) {
      ++warnings;
      const std::string before = rib.substr(0, rib.find("Light \"PxrDomeLight\""));
      EXPECT_EQ(d.loc.line, 1 + std::count(before.begin(), before.end(), '\n')) << d.str();
      EXPECT_NE(d.message.find("not found"), std::string::npos) << d.str();
    }
  EXPECT_EQ(warnings, 1);
  const Image image = render_image(rib, HiderKind::Distance);
  EXPECT_NEAR(image.at(7, 7, 1), 1.0f, 0.03f) << "a constant dome of radiance 1";
}

}  // namespace
}  // namespace darc
