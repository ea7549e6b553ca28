// Surfaces lowered to triangles render as the polygon they replace, in both hiders: a lit
// quad, once as a Polygon and once as two triangles in the scene's triangle store, with a
// sphere in front of it; and the triangle scene is the same image on 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "integrator/built_scene.h"
#include "integrator/render_frame.h"

namespace darc {
namespace {

using test::build_scene;

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

Image render(const Scene& scene, HiderKind hider, int threads) {
  Diagnostics diag([](const Diagnostic&) {});
  RenderOptions options;
  options.hider = hider;
  options.threads = threads;
  FrameStats stats;
  return render_frame(scene, options, diag, stats);
}

struct Difference {
  double rmse = 0, max = 0;
};

Difference compare(const Image& a, const Image& b) {
  Difference d;
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
    const double e = std::abs(double(a.pixels[i]) - double(b.pixels[i]));
    d.rmse += e * e;
    d.max = std::max(d.max, e);
  }
  d.rmse = std::sqrt(d.rmse / double(std::max<size_t>(1, a.pixels.size())));
  return d;
}

double mean(const Image& image) {
  double sum = 0;
  for (float v : image.pixels) sum += v;
  return sum / double(std::max<size_t>(1, image.pixels.size()));
}

TEST(TriangleSurface, RendersAsThePolygonItReplacesInBothHiders) {
  const Scene polygon = build_scene(kQuadScene);
  ASSERT_EQ(polygon.surfaces.polygons.size(), 1u);
  const Scene triangles = as_triangles(polygon);
  ASSERT_EQ(triangles.surfaces.triangles.size(), 2u);
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    SCOPED_TRACE(hider == HiderKind::Distance ? "distance" : "stochastic");
    const Image a = render(polygon, hider, 1), b = render(triangles, hider, 1);
    ASSERT_GT(mean(a), 0.05) << "the quad is lit and seen";
    const Difference d = compare(a, b);
    // The same surface: only the shared diagonal may differ, by rounding.
    EXPECT_LT(d.rmse, 2e-3);
    EXPECT_LT(d.max, 2e-2);
  }
}

TEST(TriangleSurface, SameImageOnOneAndTwoThreads) {
  const Scene triangles = as_triangles(build_scene(kQuadScene));
  for (HiderKind hider : {HiderKind::Stochastic, HiderKind::Distance}) {
    const Image one = render(triangles, hider, 1), two = render(triangles, hider, 2);
    EXPECT_EQ(one.pixels, two.pixels);
  }
}

}  // namespace
}  // namespace darc
