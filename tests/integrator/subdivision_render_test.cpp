// SubdivisionMesh end to end: a Catmull-Clark cube parsed, lowered to triangles when the scene is
// built, and rendered by both hiders.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "support/render.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build_scene;
using test::render_image;

constexpr int kSize = 96;  // pixels across the image, which spans [-1, 1] in x and y
constexpr float kPixel = 2.0f / kSize;
// The limit of the cube [-1, 1]^3 (tests/core/geometry/surfaces/subdivision/subdivision_surface_test.cpp derives both): seen
// along an axis, its outline lies between the circle through the limit face centres (radius
// 68/81, reached on the axes) and the sphere through the limit corners (radius sqrt(3)/2).
constexpr float kInnerRadius = 68.0f / 81.0f;
const float kOuterRadius = std::sqrt(3.0f) / 2.0f;
// Smooth shading: across one pixel (1/48 unit) of a surface of radius ~0.85 the normal turns
// ~0.025 rad, so a diffuse shade changes by at most ~0.05 per pixel and its second difference is a
// fraction of that; flat facets (the limit normals dropped) measure 0.09-0.10 for both.
constexpr float kSmoothStep = 0.07f, kSmoothKink = 0.06f;

// The cube, seen orthographically along +z from 5 units away, lit by a distant light from the
// upper left so that the shading varies across the whole surface.
std::string cube_scene() {
  std::ostringstream s;
  s << "Format " << kSize << " " << kSize << " 1\nPixelSamples 2 2\nPixelFilter \"box\" 1 1\n"
    << "Projection \"orthographic\"\nScreenWindow -1 1 -1 1\nWorldBegin\n"
    << "LightSource \"distantlight\" 1 \"from\" [-1 1 -1] \"to\" [0 0 0]\nSurface \"matte\"\n"
    << "Translate 0 0 5\n"
    << "SubdivisionMesh \"catmull-clark\" [4 4 4 4 4 4] [0 3 2 1  4 5 6 7  0 1 5 4  1 2 6 5  2 3 7 6  3 0 4 7] "
    << "\"P\" [-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1]\nWorldEnd\n";
  return s.str();
}

// The pixel centre's distance from the image centre, in world units.
float radius_of_pixel(int x, int y) {
  float wx = -1 + (x + 0.5f) * kPixel, wy = 1 - (y + 0.5f) * kPixel;
  return std::sqrt(wx * wx + wy * wy);
}

TEST(SubdivisionRender, CubeOutlineLiesBetweenItsLimitFaceCentresAndCorners) {
  Scene scene = build_scene(cube_scene());
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(to_string(hider));
    Image image = render_image(scene, hider, 1);
    int alpha = image.channel_index("A");
    int covered = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        float r = radius_of_pixel(x, y), a = image.at(x, y, alpha);
        if (r < kInnerRadius - kPixel) {
          EXPECT_EQ(a, 1.0f) << x << "," << y;  // no cracks between the facets
        }
        if (r > kOuterRadius + kPixel) {
          EXPECT_EQ(a, 0.0f) << x << "," << y;
        }
        covered += a > 0.5f;
      }
    }
    // Far less than the cube's square (4 units^2), about the disc's pi 0.85^2.
    float area = covered * kPixel * kPixel;
    EXPECT_GT(area, 3.14159f * kInnerRadius * kInnerRadius);
    EXPECT_LT(area, 3.14159f * kOuterRadius * kOuterRadius);
  }
}

TEST(SubdivisionRender, CubeShadingIsSmooth) {
  // With the limit normals interpolated across the triangles, the diffuse shade changes
  // gradually: the second difference of neighbouring pixels is small everywhere inside the
  // outline. (Facet normals would change the shade in steps at every triangle edge.)
  Scene scene = build_scene(cube_scene());
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(to_string(hider));
    Image image = render_image(scene, hider, 1);
    int red = image.channel_index("R");
    int compared = 0;
    float largest_step = 0, largest_kink = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 1; x + 1 < kSize; ++x) {
        if (radius_of_pixel(x - 1, y) > 0.75f || radius_of_pixel(x + 1, y) > 0.75f) continue;
        ++compared;
        float l = image.at(x - 1, y, red), c = image.at(x, y, red), r = image.at(x + 1, y, red);
        largest_step = std::max(largest_step, std::abs(r - c));
        largest_kink = std::max(largest_kink, std::abs(l - 2 * c + r));
      }
    }
    EXPECT_GT(compared, kSize * kSize / 3);  // the disc of radius 0.75
    EXPECT_GT(largest_step, 0.0f);           // the shade does vary
    EXPECT_LT(largest_step, kSmoothStep);
    EXPECT_LT(largest_kink, kSmoothKink);
  }
}

TEST(SubdivisionRender, ThreadCountDoesNotChangeTheImage) {
  Scene scene = build_scene(cube_scene());
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(to_string(hider));
    EXPECT_EQ(render_image(scene, hider, 1).pixels, render_image(scene, hider, 2).pixels);
  }
}

}  // namespace
}  // namespace darc
