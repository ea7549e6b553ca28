// Surfaces lowered to triangles render as the polygon they replace, in both hiders: a lit
// quad, once as a Polygon and once as two triangles in the scene's triangle store, with a
// sphere in front of it; and the triangle scene is the same image on 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/image_compare.h"
#include "support/pixel_measures.h"
#include "support/render.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build_scene;
using test::channel_mean;
using test::compare;
using test::ImageDifference;
using test::kRgba;
using test::render_image;

constexpr const char* kQuadScene = R"RIB(Format 48 36 1
PixelSamples 2 2
Projection "perspective" "fov" 40
Translate 0 0 5
WorldBegin
LightSource "distantlight" 1 "from" [1 2 -3] "to" [0 0 0]
LightSource "ambientlight" 2 "intensity" 0.1
Surface "matte"
AttributeBegin
  Color 0.8 0.5 0.3
  Sphere 0.6 -0.6 0.6 360
AttributeEnd
Polygon "P" [-1.5 -1.5 0.5  1.5 -1.5 0.5  1.5 1.5 2  -1.5 1.5 2]
WorldEnd
)RIB";

// The scene with its polygon replaced by two triangles of the same material (the corners are
// the RIB's: world space is the object space of the polygon).
Scene as_triangles(Scene scene) {
  const uint32_t material = scene.surfaces.polygon_material.at(0);
  scene.surfaces.polygons.clear();
  scene.surfaces.polygon_material.clear();
  TriangleMeshData m;
  m.P = {{-1.5f, -1.5f, 0.5f}, {1.5f, -1.5f, 0.5f}, {1.5f, 1.5f, 2}, {-1.5f, 1.5f, 2}};
  m.indices = {0, 1, 2, 0, 2, 3};
  scene.surfaces.triangles.add(m);
  scene.surfaces.triangle_material.assign(scene.surfaces.triangles.size(), material);
  scene.build_acceleration();
  return scene;
}

// The scene with its polygon replaced by an n x n grid of quads, two triangles each: pieces
// much smaller than a pixel when n is large.
Scene as_fine_triangles(Scene scene, int n) {
  const uint32_t material = scene.surfaces.polygon_material.at(0);
  scene.surfaces.polygons.clear();
  scene.surfaces.polygon_material.clear();
  TriangleMeshData m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float u = float(i) / float(n), v = float(j) / float(n);
      m.P.push_back({-1.5f + 3 * u, -1.5f + 3 * v, 0.5f + 1.5f * v});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1) + 1, d = a + uint32_t(n + 1);
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  scene.surfaces.triangles.add(m);
  scene.surfaces.triangle_material.assign(scene.surfaces.triangles.size(), material);
  scene.build_acceleration();
  return scene;
}

// The images are compared over RGBA only (kRgba); depth is compared by depth_ratio (the nearest
// piece in a footprint is nearer than the plane at the footprint's centre).

// The largest relative difference of the Z channels where both saw something.
double depth_ratio(const Image& a, const Image& b) {
  const int z = a.channel_index("Z");
  EXPECT_GE(z, 0);
  double worst = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const double za = a.at(x, y, z), zb = b.at(x, y, z);
      if (za > 0 && zb > 0 && std::isfinite(za) && std::isfinite(zb)) worst = std::max(worst, std::abs(za - zb) / za);
    }
  return worst;
}

TEST(TriangleSurface, RendersAsThePolygonItReplacesInBothHiders) {
  const Scene polygon = build_scene(kQuadScene);
  ASSERT_EQ(polygon.surfaces.polygons.size(), 1u);
  const Scene triangles = as_triangles(polygon);
  ASSERT_EQ(triangles.surfaces.triangles.size(), 2u);
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(hider == HiderKind::Distance ? "distance" : "stochastic");
    const Image a = render_image(polygon, hider, 1), b = render_image(triangles, hider, 1);
    ASSERT_GT(channel_mean(a), 0.05) << "the quad is lit and seen";
    const ImageDifference d = compare(a, b, kRgba);
    // The same surface: only the shared diagonal may differ, by rounding.
    EXPECT_LT(d.rmse, 2e-3);
    EXPECT_LT(d.max, 2e-2);
  }
}

// Pieces smaller than the footprint still cover it: every sub-ray of the footprint hits one of
// them, so the distance hider sees no holes between them (the mesh is watertight).
TEST(TriangleSurface, PiecesSmallerThanAPixelCoverTheirFootprint) {
  const Scene polygon = build_scene(kQuadScene);
  const Scene fine = as_fine_triangles(polygon, 200);  // about 8 pieces across a pixel
  ASSERT_EQ(fine.surfaces.triangles.size(), 80000u);
  const Image a = render_image(polygon, HiderKind::Distance, 1), b = render_image(fine, HiderKind::Distance, 1);
  const ImageDifference d = compare(a, b, kRgba);
  EXPECT_LT(d.rmse, 2e-3);
  EXPECT_LT(d.max, 2e-2);
  // The plane is tilted 27 degrees to the view: across one pixel footprint its depth changes by
  // about 1 % of the depth.
  EXPECT_LT(depth_ratio(a, b), 1e-2) << "depth: the nearest piece, within the footprint's depth range";
}

// The same for the faces of a polygon mesh (what exporters write for most geometry).
TEST(TriangleSurface, PolygonMeshFacesSmallerThanAPixelCoverTheirFootprint) {
  constexpr int n = 150;
  std::string rib = kQuadScene;
  std::string mesh = "PointsPolygons [";
  for (int k = 0; k < n * n; ++k) mesh += "4 ";
  mesh += "] [";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      mesh += std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + n + 2) + " " +
              std::to_string(a + n + 1) + " ";
    }
  mesh += "] \"P\" [";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = double(i) / n, v = double(j) / n;
      mesh += std::to_string(-1.5 + 3 * u) + " " + std::to_string(-1.5 + 3 * v) + " " + std::to_string(0.5 + 1.5 * v) + " ";
    }
  mesh += "]";
  const std::string polygon_line = "Polygon \"P\" [-1.5 -1.5 0.5  1.5 -1.5 0.5  1.5 1.5 2  -1.5 1.5 2]";
  rib.replace(rib.find(polygon_line), polygon_line.size(), mesh);
  const Scene polygon = build_scene(kQuadScene), faces = build_scene(rib);
  ASSERT_EQ(faces.surfaces.polygons.size(), size_t(n * n));
  const ImageDifference d =
      compare(render_image(polygon, HiderKind::Distance, 1), render_image(faces, HiderKind::Distance, 1), kRgba);
  EXPECT_LT(d.rmse, 2e-3);
  EXPECT_LT(d.max, 2e-2);
}

TEST(TriangleSurface, SameImageOnOneAndTwoThreads) {
  const Scene triangles = as_triangles(build_scene(kQuadScene));
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    const Image one = render_image(triangles, hider, 1), two = render_image(triangles, hider, 2);
    EXPECT_EQ(one.pixels, two.pixels);
  }
}

}  // namespace
}  // namespace darc
