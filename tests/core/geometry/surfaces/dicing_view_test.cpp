// The dicing view (how large a pixel is where a surface lies) and the tessellation that follows
// the screen with it: a pixel's size against the camera's geometry, perspective and
// orthographic, through a scaling transform; a NURBS sphere far away gets fewer triangles than
// the surface rules alone ask, its chords stay within kMaxDeviationPixels of the sphere, and
// near the eye the screen never asks for more than the surface rules; a subdivision mesh far
// away gets fewer levels.
#include "core/geometry/surfaces/dicing_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/surfaces/patches/nurbs_tessellation.h"
#include "core/geometry/surfaces/patches/parametric_grid.h"
#include "core/geometry/surfaces/subdivision/subdivision_surface.h"

namespace darc {
namespace {

// A unit sphere as a NuPatch of rational quadratic arcs (9 x 5 points, "Pw").
NurbsSurfaceDescription unit_sphere() {
  const double h = std::sqrt(0.5);
  const double ax[] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ay[] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  const double aw[] = {1, h, 1, h, 1, h, 1, h, 1};
  const double px[] = {0, 1, 1, 1, 0}, pz[] = {-1, -1, 0, 1, 1}, pw[] = {1, h, 1, h, 1};
  NurbsSurfaceDescription s;
  s.u = {9, 3, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}, 0, 4};
  s.v = {5, 3, {0, 0, 0, 1, 1, 2, 2, 2}, 0, 2};
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 9; ++i) {
      const double w = aw[i] * pw[j];
      s.points.push_back({{ax[i] * px[j] * w, ay[i] * px[j] * w, pz[j] * w}, w});
    }
  return s;
}

// A perspective camera of field of view `fov` at 100 x 100 looking at a sphere `distance` away.
DicingView view_at(double distance, double fov = 90, int res = 100) {
  return make_dicing_view(Matrix4::translate({0, 0, distance}), Matrix4{}, true, fov, 2, 2, res, res);
}

// The largest distance of a triangle edge's midpoint from the unit sphere (the chords' sag).
double largest_sag(const TriangleMeshData& mesh) {
  double sag = 0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const Vec3d a(mesh.P[mesh.indices[t + size_t(k)]]), b(mesh.P[mesh.indices[t + size_t(k + 1) % 3]]);
      sag = std::max(sag, 1.0 - length((a + b) * 0.5));
    }
  return sag;
}

// A pixel's size as the view gives it: never over the exact one, and within the 1 % its bound
// of the transform's stretch allows.
void expect_pixel(const DicingView& v, const Vec3d& P, double exact) {
  const double size = v.pixel_size(P);
  EXPECT_LE(size, exact * (1 + 1e-12));
  EXPECT_GE(size, exact * 0.989);
}

TEST(DicingView, PixelSizeFollowsDepthFieldOfViewAndScale) {
  // fov 90: the screen's [-1, 1] spans depth 1's [-1, 1], so a pixel of 100 is 0.02 there.
  const DicingView v = view_at(10);
  expect_pixel(v, {0, 0, 0}, 10 * 0.02);
  expect_pixel(v, {0, 0, -5}, 5 * 0.02);
  // Behind the eye: by distance (seen in shadows and reflections only).
  expect_pixel(v, {0, 3, -14}, 5 * 0.02);
  // Object space scaled by 4: a pixel is a quarter as long there; scaled unevenly, the largest
  // stretch counts.
  expect_pixel(make_dicing_view(Matrix4::scale({4, 4, 4}) * Matrix4::translate({0, 0, 10}), Matrix4{}, true, 90, 2,
                                2, 100, 100),
               {0, 0, 0}, 10 * 0.02 / 4);
  expect_pixel(make_dicing_view(Matrix4::scale({1, 5, 2}) * Matrix4::rotate(30, {1, 1, 0}) *
                                    Matrix4::translate({0, 0, 10}),
                                Matrix4{}, true, 90, 2, 2, 100, 100),
               {0, 0, 0}, 10 * 0.02 / 5);
  // Orthographic: the same everywhere, the screen window's width over the resolution.
  const DicingView ortho = make_dicing_view(Matrix4{}, Matrix4{}, false, 90, 8, 6, 400, 200);
  expect_pixel(ortho, {0, 0, 1}, 0.02);
  expect_pixel(ortho, {5, 0, 100}, 0.02);
}

TEST(DicingView, FarSphereGetsFewerTrianglesWithinTheDeviationInPixels) {
  std::string error;
  const TriangleMeshData surface = tessellate_nurbs(unit_sphere(), error);
  ASSERT_EQ(error, "");
  // 20 units away at fov 40 on 100 pixels: the sphere is about 14 pixels wide.
  const DicingView far = view_at(20, 40);
  const TriangleMeshData screen = tessellate_nurbs(unit_sphere(), error, &far);
  ASSERT_EQ(error, "");
  EXPECT_LT(screen.triangle_count() * 4, surface.triangle_count());
  // The chords stay within the deviation asked for, at the sphere's nearest pixel size.
  const double pixel = far.pixel_size({0, 0, -1});
  EXPECT_LE(largest_sag(screen), kMaxDeviationPixels * pixel);
  EXPECT_GT(largest_sag(screen), largest_sag(surface)) << "coarser than the surface rules";
}

TEST(DicingView, NearSphereKeepsTheSurfaceRules) {
  // 1.5 units away at fov 90 on 2000 pixels: hundreds of pixels a radian, finer than the surface
  // rules would go; the screen only ever lowers the counts.
  std::string error;
  const TriangleMeshData surface = tessellate_nurbs(unit_sphere(), error);
  const DicingView near = view_at(1.5, 90, 2000);
  const TriangleMeshData screen = tessellate_nurbs(unit_sphere(), error, &near);
  EXPECT_EQ(screen.triangle_count(), surface.triangle_count());
}

TEST(DicingView, SubdivisionLevelsBringTheLongestEdgeToAPixel) {
  EXPECT_EQ(subdivision_levels_on_screen(100, 4), 4);  // 100 / 16 is still over a pixel
  EXPECT_EQ(subdivision_levels_on_screen(3, 4), 2);    // 3 / 4 is under one
  EXPECT_EQ(subdivision_levels_on_screen(0.5, 4), 1);  // at least one level
  EXPECT_EQ(subdivision_levels_on_screen(INFINITY, 3), 3);
  // A unit cube: 4 levels by its size; 200 units away at fov 40 on 100 pixels its edges are
  // 0.7 pixel, so one level; 3 units away, 20 pixels, all four.
  SubdivisionMeshRequest cube;
  cube.scheme = "catmull-clark";
  cube.P = {{-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, -0.5f}, {-0.5f, 0.5f, -0.5f},
            {-0.5f, -0.5f, 0.5f},  {0.5f, -0.5f, 0.5f},  {0.5f, 0.5f, 0.5f},  {-0.5f, 0.5f, 0.5f}};
  cube.nvertices = {4, 4, 4, 4, 4, 4};
  cube.vertices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 3, 0, 4, 7};
  const SubdivisionTessellation alone = tessellate_subdivision_mesh(cube);
  ASSERT_TRUE(alone.ok()) << alone.error;
  EXPECT_EQ(alone.levels, 4);
  const DicingView far = view_at(200, 40), near = view_at(3, 40);
  const SubdivisionTessellation small = tessellate_subdivision_mesh(cube, &far);
  EXPECT_EQ(small.levels, 1);
  EXPECT_LT(small.mesh.triangle_count() * 16, alone.mesh.triangle_count());
  EXPECT_EQ(tessellate_subdivision_mesh(cube, &near).levels, 4);
}

}  // namespace
}  // namespace darc
