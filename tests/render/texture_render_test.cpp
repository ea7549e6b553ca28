// Textures rendered end to end: paintedplastic reads its "texturename" through OpenImageIO at
// the (s, t) a surface gives (a polygon's "st", a patch's or a quadric's parameters), filtered
// by the hit's footprint, so that the distance hider's one ray per pixel reads a receding
// checkerboard as 16x16 point samples do (lookdev.md §4); a missing file is a warning and the
// shader's documented fallback.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <sstream>
#include <string>

#include "support/darc_command.h"
#include "support/render.h"
#include "support/scenes_from_rib.h"
#include "support/texture_files.h"

namespace darc {
namespace {

using test::render_image;
using test::ScratchDir;

// A 256x256 texture of 16x16 checks of 0.1 and 0.9, MIP-mapped by OIIO's maketx.
std::string make_checker(const ScratchDir& dir) {
  OIIO::ImageBuf flat(OIIO::ImageSpec(256, 256, 3, OIIO::TypeDesc::FLOAT));
  const float dark[3] = {0.1f, 0.1f, 0.1f}, light[3] = {0.9f, 0.9f, 0.9f};
  OIIO::ImageBufAlgo::checker(flat, 16, 16, 1, dark, light);
  const std::string path = (dir / "checker.tx").string();
  OIIO::ImageSpec config;
  config.attribute("wrapmodes", "periodic,periodic");
  EXPECT_TRUE(OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, flat, path, config));
  return path;
}

// A plane y = 0 seen from just above, receding to the horizon, its st repeating the checker
// 10 times across and 15 times in depth; ambient light only, so the image is the texture.
std::string receding_plane(const std::string& texture, int samples) {
  std::ostringstream s;
  s << "Format 160 120 1\nPixelSamples " << samples << " " << samples << "\nPixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [50]\nRotate -15 1 0 0\nTranslate 0 -1 1\nWorldBegin\n"
    << "LightSource \"ambientlight\" 1 \"intensity\" [1]\n"
    << "Surface \"paintedplastic\" \"texturename\" [\"" << texture << "\"] \"Kd\" [0] \"Ks\" [0]\n"
    << "Polygon \"P\" [-20 0 0  20 0 0  20 0 60  -20 0 60] \"st\" [0 0  10 0  10 15  0 15]\nWorldEnd\n";
  return s.str();
}

double rmse(const Image& a, const Image& b) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c, ++n) sum += std::pow(double(a.at(x, y, c)) - b.at(x, y, c), 2);
  return std::sqrt(sum / n);
}

TEST(TextureRender, ARecedingCheckerboardAtOneRayPerPixelMatchesSixteenBySixteenPointSamples) {
  ScratchDir dir("receding_checkerboard");
  const std::string texture = make_checker(dir);
  const Image reference = render_image(receding_plane(texture, 16), HiderKind::Stochastic);
  const Image filtered = render_image(receding_plane(texture, 1), HiderKind::Distance);
  const Image point = render_image(receding_plane(texture, 1), HiderKind::Stochastic);
  const double filtered_error = rmse(filtered, reference), point_error = rmse(point, reference);
  EXPECT_LE(filtered_error, 0.02);
  // The same one ray per pixel point-sampled aliases: the footprint is what filters.
  EXPECT_GT(point_error, 4 * filtered_error);
  // Rows near the horizon (the plane ends at row 29), where a pixel holds many checks: grey, not
  // the checks' moire (point samples there are 0.1 or 0.9).
  double far_spread = 0, point_spread = 0;
  for (int y = 31; y <= 35; ++y)
    for (int x = 0; x < 160; ++x) {
      far_spread = std::max(far_spread, std::abs(double(filtered.at(x, y, 0)) - 0.5));
      point_spread = std::max(point_spread, std::abs(double(point.at(x, y, 0)) - 0.5));
    }
  EXPECT_LT(far_spread, 0.1);
  EXPECT_GT(point_spread, 0.3);
}

// The texture's orientation: s runs left to right across the image and t down it (RI's and
// OIIO's convention); on a bilinear patch s = u and t = v; on a polygon its "st".
TEST(TextureRender, SRunsAcrossTheImageAndTDownItOnPatchesAndPolygons) {
  ScratchDir dir("texture_orientation");
  const std::string texture = test::write_quadrants_texture(dir);
  // Seen from +z looking down -z: x to the right, y up. The patch's u runs along +x, v along -y,
  // so its top left is (s, t) = (0, 0): bright red.
  const std::string head = "Format 8 8 1\nPixelSamples 1 1\nProjection \"orthographic\"\nTranslate 0 0 5\nWorldBegin\n"
                           "LightSource \"ambientlight\" 1 \"intensity\" [1]\nSurface \"paintedplastic\" \"texturename\" [\"" +
                           texture + "\"] \"Kd\" [0] \"Ks\" [0]\n";
  const std::string patch = head + "Patch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\nWorldEnd\n";
  const std::string polygon =
      head + "Polygon \"P\" [-1 1 0  1 1 0  1 -1 0  -1 -1 0] \"st\" [0 0  1 0  1 1  0 1]\nWorldEnd\n";
  for (const std::string& rib : {patch, polygon})
    for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
      const Image image = render_image(rib, hider);
      EXPECT_NEAR(image.at(1, 1, 0), 1.0f, 0.02f) << to_string(hider);   // top left: bright red
      EXPECT_NEAR(image.at(6, 1, 2), 1.0f, 0.02f) << to_string(hider);   // top right: bright blue
      EXPECT_NEAR(image.at(1, 6, 0), 0.5f, 0.02f) << to_string(hider);   // bottom left: dim red
      EXPECT_NEAR(image.at(6, 6, 2), 0.5f, 0.02f) << to_string(hider);   // bottom right: dim blue
      EXPECT_NEAR(image.at(1, 1, 2), 0.0f, 0.02f) << to_string(hider);
    }
}

// An 8x8 orthographic view of [-1, 1]^2 from +z (box filter, one sample per pixel) up to a
// paintedplastic of `texture` under an ambient light of 1: a pixel shows the texel it sees.
std::string textured_view(const std::string& texture) {
  return "Format 8 8 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\nProjection \"orthographic\"\nTranslate 0 0 5\nWorldBegin\n"
         "LightSource \"ambientlight\" 1 \"intensity\" [1]\nSurface \"paintedplastic\" \"texturename\" [\"" +
         texture + "\"] \"Kd\" [0] \"Ks\" [0]\n";
}

// The quadrants texture on a square whose st is mirrored in s (s = 1 at its left, 0 at its
// right; t = 0 at its top): top left bright blue, top right bright red, bottom right dim red.
void expect_mirrored_quadrants(const Image& m, HiderKind hider) {
  EXPECT_NEAR(m.at(1, 1, 2), 1.0f, 0.02f) << to_string(hider);  // top left: bright blue
  EXPECT_NEAR(m.at(1, 1, 0), 0.0f, 0.02f) << to_string(hider);
  EXPECT_NEAR(m.at(6, 1, 0), 1.0f, 0.02f) << to_string(hider);  // top right: bright red
  EXPECT_NEAR(m.at(6, 6, 0), 0.5f, 0.02f) << to_string(hider);  // bottom right: dim red
}

// Two patches (or segments) side by side whose s runs 0.5 to 1 over the left one and 1 to 0 over
// the right one, t 0 at the top: the left one blue, the right one blue then red past its middle.
void expect_s_runs_over_two_patches(const Image& p, HiderKind hider) {
  EXPECT_NEAR(p.at(1, 1, 2), 1.0f, 0.02f) << to_string(hider);  // left one, top: bright blue
  EXPECT_NEAR(p.at(6, 1, 0), 1.0f, 0.02f) << to_string(hider);  // right one, top (s 0.375): bright red
  EXPECT_NEAR(p.at(6, 6, 0), 0.5f, 0.02f) << to_string(hider);  // right one, bottom: dim red
  EXPECT_NEAR(p.at(5, 1, 2), 1.0f, 0.02f) << to_string(hider);  // s 0.625 there: bright blue
}

// Curves read textures by their "st" (or "s", "t") primvars: uniform st gives a strand one texel
// (a scalp map), vertex st follows the strand. The quadrants texture: (s, t) < (0.5, 0.5) bright
// red, s > 0.5 bright blue, t > 0.5 the dim halves (0.5).
TEST(TextureRender, CurvesReadTexturesByTheirStPrimvars) {
  ScratchDir dir("texture_curves");
  const std::string texture = test::write_quadrants_texture(dir);
  const std::string head = textured_view(texture);
  // Two horizontal strands, y = 0.5 (rows 1, 2) and y = -0.5 (rows 5, 6), one st each.
  const std::string uniform =
      head + "Curves \"linear\" [2 2] \"nonperiodic\" \"P\" [-2 0.5 0  2 0.5 0  -2 -0.5 0  2 -0.5 0] "
             "\"constantwidth\" [0.5] \"uniform float[2] st\" [0.25 0.25  0.75 0.75]\nWorldEnd\n";
  // The same with "s" and "t" apart.
  const std::string apart =
      head + "Curves \"linear\" [2 2] \"nonperiodic\" \"P\" [-2 0.5 0  2 0.5 0  -2 -0.5 0  2 -0.5 0] "
             "\"constantwidth\" [0.5] \"uniform float s\" [0.25 0.75] \"uniform float t\" [0.25 0.75]\nWorldEnd\n";
  // One vertical strand at x = 0 (columns 3, 4) whose t runs from 0 at the top to 1 at the bottom.
  const std::string along =
      head + "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [0 1 0  0 0.33 0  0 -0.33 0  0 -1 0] "
             "\"constantwidth\" [0.5] \"vertex float[2] st\" [0.25 0  0.25 0.333  0.25 0.667  0.25 1]\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    for (const std::string& rib : {uniform, apart}) {
      const Image image = render_image(rib, hider);
      for (int x = 1; x < 7; ++x) {
        EXPECT_NEAR(image.at(x, 1, 0), 1.0f, 0.02f) << to_string(hider) << " x " << x;  // bright red
        EXPECT_NEAR(image.at(x, 1, 2), 0.0f, 0.02f) << to_string(hider) << " x " << x;
        EXPECT_NEAR(image.at(x, 6, 2), 0.5f, 0.02f) << to_string(hider) << " x " << x;  // dim blue
        EXPECT_NEAR(image.at(x, 6, 0), 0.0f, 0.02f) << to_string(hider) << " x " << x;
      }
    }
    // Bezier basis, vertex st at the control points: t is linear along the strand (the control
    // points are evenly spaced), so t < 0.5 above y = 0.
    const Image image = render_image(along, hider);
    for (int x : {3, 4}) {
      EXPECT_NEAR(image.at(x, 1, 0), 1.0f, 0.02f) << to_string(hider);  // top: bright red
      EXPECT_NEAR(image.at(x, 6, 0), 0.5f, 0.02f) << to_string(hider);  // bottom: dim red
      EXPECT_NEAR(image.at(x, 6, 2), 0.0f, 0.02f) << to_string(hider);
    }
  }
}

// A patch's "st" (varying: one value per corner, bilinear between) replaces its (u, v): mirrored
// in s, its top left shows the texture's top right. On a PatchMesh of two patches the corners'
// values hold per patch, and "s", "t" apart do the same.
TEST(TextureRender, APatchsStPrimvarMapsItsCorners) {
  ScratchDir dir("texture_patch_st");
  const std::string texture = test::write_quadrants_texture(dir);
  const std::string head = textured_view(texture);
  const std::string mirrored = head + "Patch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0] "
                                      "\"varying float[2] st\" [1 0  0 0  1 1  0 1]\nWorldEnd\n";
  // Two patches side by side (u runs over both): s runs from 0.5 to 1 over the left one (blue) and
  // back from 1 to 0 over the right one (blue, then red past its middle); t as usual.
  const std::string mesh = head + "PatchMesh \"bilinear\" 3 \"nonperiodic\" 2 \"nonperiodic\" "
                                  "\"P\" [-1 1 0  0 1 0  1 1 0  -1 -1 0  0 -1 0  1 -1 0] "
                                  "\"varying float s\" [0.5 1 0  0.5 1 0] \"varying float t\" [0 0 0  1 1 1]\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    expect_mirrored_quadrants(render_image(mirrored, hider), hider);
    expect_s_runs_over_two_patches(render_image(mesh, hider), hider);
  }
}

// A NuPatch's "st": varying (one value per segment corner) mirrors a bilinear NuPatch as the
// Patch test does, and vertex st (one per control point) the same; over two segments in u the
// values hold per segment corner, as on the PatchMesh.
TEST(TextureRender, ANuPatchsStPrimvarMapsItsSegmentCorners) {
  ScratchDir dir("texture_nupatch_st");
  const std::string texture = test::write_quadrants_texture(dir);
  const std::string head = textured_view(texture);
  const std::string square = "NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0] ";
  const std::string varying = head + square + "\"varying float[2] st\" [1 0  0 0  1 1  0 1]\nWorldEnd\n";
  const std::string vertex = head + square + "\"vertex float[2] st\" [1 0  0 0  1 1  0 1]\nWorldEnd\n";
  const std::string segments = head + "NuPatch 3 2 [0 0 0.5 1 1] 0 1 2 2 [0 0 1 1] 0 1 "
                                      "\"P\" [-1 1 0  0 1 0  1 1 0  -1 -1 0  0 -1 0  1 -1 0] "
                                      "\"varying float s\" [0.5 1 0  0.5 1 0] \"varying float t\" [0 0 0  1 1 1]\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    for (const std::string* rib : {&varying, &vertex}) expect_mirrored_quadrants(render_image(*rib, hider), hider);
    expect_s_runs_over_two_patches(render_image(segments, hider), hider);
  }
}

// Points read "st" (or "s", "t") per point or shared: each point is one texel.
TEST(TextureRender, PointsReadOneTexelEach) {
  ScratchDir dir("texture_points_st");
  const std::string texture = test::write_quadrants_texture(dir);
  const std::string head = textured_view(texture) + "Points \"P\" [-0.5 0.5 0  0.5 0.5 0  -0.5 -0.5 0  0.5 -0.5 0] "
                                                    "\"constantwidth\" [0.9] ";
  const std::string per_point = head + "\"vertex float[2] st\" [0.75 0.25  0.25 0.25  0.75 0.75  0.25 0.75]\nWorldEnd\n";
  const std::string shared = head + "\"constant float s\" [0.75] \"constant float t\" [0.75]\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    const Image p = render_image(per_point, hider);
    EXPECT_NEAR(p.at(2, 2, 2), 1.0f, 0.02f) << to_string(hider);  // top left: bright blue
    EXPECT_NEAR(p.at(5, 2, 0), 1.0f, 0.02f) << to_string(hider);  // top right: bright red
    EXPECT_NEAR(p.at(2, 5, 2), 0.5f, 0.02f) << to_string(hider);  // bottom left: dim blue
    EXPECT_NEAR(p.at(5, 5, 0), 0.5f, 0.02f) << to_string(hider);  // bottom right: dim red
    EXPECT_NEAR(p.at(5, 5, 2), 0.0f, 0.02f) << to_string(hider);
    const Image c = render_image(shared, hider);
    for (auto [x, y] : {std::pair{2, 2}, {5, 2}, {2, 5}, {5, 5}}) {
      EXPECT_NEAR(c.at(x, y, 2), 0.5f, 0.02f) << to_string(hider);  // dim blue everywhere
      EXPECT_NEAR(c.at(x, y, 0), 0.0f, 0.02f) << to_string(hider);
    }
  }
}

// A subdivision mesh reads "st" of every class: facevarying and vertex st mirror a square (a
// quad with its boundary interpolated: a bilinear patch, whose st is bilinear too), uniform st
// gives each face one texel.
TEST(TextureRender, ASubdivisionMeshReadsItsSt) {
  ScratchDir dir("texture_subdivision_st");
  const std::string texture = test::write_quadrants_texture(dir);
  const std::string head = textured_view(texture) + "SubdivisionMesh \"catmull-clark\" ";
  const std::string quad = "[4] [0 1 3 2] [\"interpolateboundary\"] [0 0] [] [] \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0] ";
  const std::string facevarying = head + quad + "\"facevarying float[2] st\" [1 0  0 0  0 1  1 1]\nWorldEnd\n";
  const std::string vertex = head + quad + "\"vertex float s\" [1 0 1 0] \"vertex float t\" [0 0 1 1]\nWorldEnd\n";
  const std::string uniform = head + "[4 4] [0 1 4 3  1 2 5 4] [\"interpolateboundary\"] [0 0] [] [] "
                                     "\"P\" [-1 1 0  0 1 0  1 1 0  -1 -1 0  0 -1 0  1 -1 0] "
                                     "\"uniform float[2] st\" [0.25 0.75  0.75 0.25]\nWorldEnd\n";
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    for (const std::string* rib : {&facevarying, &vertex}) {
      const Image m = render_image(*rib, hider);
      expect_mirrored_quadrants(m, hider);
      EXPECT_NEAR(m.at(1, 6, 2), 0.5f, 0.02f) << to_string(hider);  // bottom left: dim blue
    }
    const Image u = render_image(uniform, hider);
    for (int y : {1, 6}) {
      EXPECT_NEAR(u.at(1, y, 0), 0.5f, 0.02f) << to_string(hider);  // left face: (0.25, 0.75), dim red
      EXPECT_NEAR(u.at(6, y, 2), 1.0f, 0.02f) << to_string(hider);  // right face: (0.75, 0.25), bright blue
    }
  }
}

// A sphere's s follows its longitude: the texture's left half is on one side of it.
TEST(TextureRender, ASphereIsTexturedByItsParameters) {
  ScratchDir dir("texture_sphere");
  const std::string texture = test::write_quadrants_texture(dir);
  // Looking down the sphere's -z axis from +z: longitudes 0-180 degrees (u < 0.5, red) are at y > 0.
  const std::string rib = "Format 16 16 1\nPixelSamples 1 1\nProjection \"orthographic\"\nScreenWindow -1.2 1.2 -1.2 1.2\n"
                          "Translate 0 0 5\nWorldBegin\nLightSource \"ambientlight\" 1 \"intensity\" [1]\n"
                          "Surface \"paintedplastic\" \"texturename\" [\"" +
                          texture + "\"] \"Kd\" [0] \"Ks\" [0]\nSphere 1 -1 1 360\nWorldEnd\n";
  const Image image = render_image(rib, HiderKind::Distance);
  EXPECT_GT(image.at(8, 3, 0), 0.4f);   // above the centre (y > 0): red
  EXPECT_LT(image.at(8, 3, 2), 0.05f);
  EXPECT_GT(image.at(8, 12, 2), 0.4f);  // below: blue
  EXPECT_LT(image.at(8, 12, 0), 0.05f);
}

TEST(TextureRender, AMissingTextureWarnsWhereTheRibNamesItAndShadesWithCs) {
  const std::string rib =
      "Format 4 4 1\nPixelSamples 1 1\nProjection \"orthographic\"\nTranslate 0 0 5\nWorldBegin\n"
      "LightSource \"ambientlight\" 1 \"intensity\" [1]\nColor 0.3 0.6 0.9\n"
      "Surface \"paintedplastic\" \"texturename\" [\"no-such-texture.tx\"] \"Kd\" [0] \"Ks\" [0]\n"
      "Polygon \"P\" [-1 1 0  1 1 0  1 -1 0  -1 -1 0]\nWorldEnd\n";
  const test::Built built = test::build(rib);
  ASSERT_EQ(built.scenes.size(), 1u);
  int warnings = 0;
  for (const Diagnostic& d : built.diagnostics)
    if (d.severity == Severity::Warning && d.message.find("no-such-texture.tx") != std::string::npos) {
      ++warnings;
      EXPECT_EQ(d.loc.line, 8) << d.str();
      EXPECT_NE(d.message.find("not found"), std::string::npos) << d.str();
    }
  EXPECT_EQ(warnings, 1);
  const Image image = render_image(rib, HiderKind::Distance);
  EXPECT_NEAR(image.at(2, 2, 0), 0.3f, 1e-4f);
  EXPECT_NEAR(image.at(2, 2, 2), 0.9f, 1e-4f);
}

TEST(TextureRender, ATextureIsFoundAlongTheTextureSearchPath) {
  ScratchDir dir("texture_searchpath");
  test::write_quadrants_texture(dir);
  const std::string rib = "Option \"searchpath\" \"texture\" [\"/nonexistent:" + dir.path().string() +
                          "\"]\nFormat 8 8 1\nPixelSamples 1 1\nProjection \"orthographic\"\nTranslate 0 0 5\nWorldBegin\n"
                          "LightSource \"ambientlight\" 1 \"intensity\" [1]\n"
                          "Surface \"paintedplastic\" \"texturename\" [\"quadrants.exr\"] \"Kd\" [0] \"Ks\" [0]\n"
                          "Patch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\nWorldEnd\n";
  const test::Built built = test::build(rib);
  for (const Diagnostic& d : built.diagnostics) ADD_FAILURE() << "unexpected: " << d.str();
  const Image image = render_image(rib, HiderKind::Distance);
  EXPECT_NEAR(image.at(1, 1, 0), 1.0f, 0.02f);
  EXPECT_NEAR(image.at(6, 6, 2), 0.5f, 0.02f);
}

}  // namespace
}  // namespace darc
