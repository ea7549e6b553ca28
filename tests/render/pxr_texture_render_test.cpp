// PxrTexture feeding a RIS Bxdf's colour, rendered end to end: the texture at the primitive's
// (s, t) through its PxrManifold2D (scale, offset, inversion), t inverted by default as RenderMan
// does for DCC UVs, sRGB decoded with "linearize", and the missingColor (magenta by default) with
// a warning when the file is not found.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/darc_command.h"
#include "support/render.h"
#include "support/scenes_from_rib.h"
#include "support/texture_files.h"

namespace darc {
namespace {

using test::render_image;
using test::ScratchDir;

// A square with st (0, 0) at its top left seen face on, 8 x 8 pixels, under an ambient light of 1:
// the image is the Bxdf's colour (PxrDiffuse -> matte, Ka 1).
std::string square(const std::string& patterns, const std::string& bxdf_colour) {
  return "Format 8 8 1\nPixelSamples 1 1\nProjection \"orthographic\"\nTranslate 0 0 5\nWorldBegin\n"
         "LightSource \"ambientlight\" 1 \"intensity\" [1]\n" +
         patterns + "Bxdf \"PxrDiffuse\" \"d\" " + bxdf_colour +
         "\nPolygon \"P\" [-1 1 0  1 1 0  1 -1 0  -1 -1 0] \"st\" [0 0  1 0  1 1  0 1]\nWorldEnd\n";
}

std::string texture_pattern(const std::string& file, const std::string& extra = "") {
  return "Pattern \"PxrTexture\" \"tex\" \"string filename\" [\"" + file + "\"] " + extra + "\n";
}

const std::string kFed = "\"reference color diffuseColor\" [\"tex:resultRGB\"]";

TEST(PxrTextureRender, InvertTZeroReadsTheTextureAsPaintedplasticDoes) {
  ScratchDir dir("pxr_texture_plain");
  const std::string file = test::write_quadrants_texture(dir);
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image image = render_image(square(texture_pattern(file, "\"int invertT\" [0]"), kFed), hider);
    EXPECT_NEAR(image.at(1, 1, 0), 1.0f, 0.02f) << to_string(hider);  // top left: bright red
    EXPECT_NEAR(image.at(6, 1, 2), 1.0f, 0.02f) << to_string(hider);  // top right: bright blue
    EXPECT_NEAR(image.at(1, 6, 0), 0.5f, 0.02f) << to_string(hider);  // bottom left: dim red
    EXPECT_NEAR(image.at(6, 6, 2), 0.5f, 0.02f) << to_string(hider);
  }
}

TEST(PxrTextureRender, TIsInvertedByDefault) {
  ScratchDir dir("pxr_texture_invert");
  const std::string file = test::write_quadrants_texture(dir);
  const Image image = render_image(square(texture_pattern(file), kFed), HiderKind::Distance);
  EXPECT_NEAR(image.at(1, 1, 0), 0.5f, 0.02f) << "the top shows the texture's bottom";
  EXPECT_NEAR(image.at(1, 6, 0), 1.0f, 0.02f);
  EXPECT_NEAR(image.at(6, 6, 2), 1.0f, 0.02f);
}

TEST(PxrTextureRender, AManifoldScalesAndOffsetsST) {
  ScratchDir dir("pxr_texture_manifold");
  const std::string file = test::write_quadrants_texture(dir);
  // s' = 2 s + 0.5: the left quarter of the square (s < 0.25) reads s' in [0.5, 1), blue; the next
  // quarter wraps to [0, 0.5), red. invertT 0 on both nodes: t as it is.
  const std::string patterns = "Pattern \"PxrManifold2D\" \"m\" \"float scaleS\" [2] \"float offsetS\" [0.5] \"int invertT\" [0]\n" +
                               texture_pattern(file, "\"int invertT\" [0] \"reference struct manifold\" [\"m:result\"]");
  const Image image = render_image(square(patterns, kFed), HiderKind::Distance);
  EXPECT_NEAR(image.at(0, 1, 2), 1.0f, 0.05f);
  EXPECT_NEAR(image.at(0, 1, 0), 0.0f, 0.05f);
  EXPECT_NEAR(image.at(3, 1, 0), 1.0f, 0.05f);
  EXPECT_NEAR(image.at(5, 1, 2), 1.0f, 0.05f);
  EXPECT_NEAR(image.at(7, 1, 0), 1.0f, 0.05f);
}

TEST(PxrTextureRender, LinearizeDecodesSrgb) {
  ScratchDir dir("pxr_texture_linearize");
  const std::string file = test::write_quadrants_texture(dir);
  const Image image =
      render_image(square(texture_pattern(file, "\"int invertT\" [0] \"int linearize\" [1]"), kFed), HiderKind::Distance);
  EXPECT_NEAR(image.at(1, 1, 0), 1.0f, 0.02f);
  EXPECT_NEAR(image.at(1, 6, 0), 0.2140f, 0.01f) << "sRGB 0.5 is linear 0.214";
}

TEST(PxrTextureRender, AMissingFileIsAWarningAndTheMissingColour) {
  const std::string rib = square(texture_pattern("no_such_texture.tex"), kFed);
  const test::Built built = test::build(rib);
  int warnings = 0;
  for (const Diagnostic& d : built.diagnostics)
    if (d.severity == Severity::Warning && d.message.find("no_such_texture.tex") != std::string::npos) {
      ++warnings;
      EXPECT_NE(d.message.find("missingColor"), std::string::npos) << d.str();
      const std::string before = rib.substr(0, rib.find("Bxdf"));
      EXPECT_EQ(d.loc.line, 1 + std::count(before.begin(), before.end(), '\n')) << d.str();
    }
  EXPECT_EQ(warnings, 1);
  const Image image = render_image(rib, HiderKind::Distance);
  EXPECT_NEAR(image.at(4, 4, 0), 1.0f, 1e-4f) << "magenta, RenderMan's default missingColor";
  EXPECT_NEAR(image.at(4, 4, 1), 0.0f, 1e-4f);
  EXPECT_NEAR(image.at(4, 4, 2), 1.0f, 1e-4f);
  const Image green = render_image(
      square(texture_pattern("no_such_texture.tex", "\"color missingColor\" [0 1 0]"), kFed), HiderKind::Distance);
  EXPECT_NEAR(green.at(4, 4, 1), 1.0f, 1e-4f);
  EXPECT_NEAR(green.at(4, 4, 0), 0.0f, 1e-4f);
}

}  // namespace
}  // namespace darc
