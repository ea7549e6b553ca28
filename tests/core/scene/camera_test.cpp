// RI camera conventions: left-handed camera space looking down +z, x right, y up, fov on the
// shorter image axis, raster y down.
#include "core/scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace darc {
namespace {

Camera perspective_camera(int xres, int yres, double fov) {
  Camera c;
  c.projection = Camera::Projection::Perspective;
  c.fov_degrees = fov;
  c.xres = xres;
  c.yres = yres;
  c.screen = default_screen_window(double(xres) / yres);
  c.finalize();
  return c;
}

TEST(Camera, PlusXLandsRightOfCentreAndPlusYAbove) {
  Camera c = perspective_camera(320, 240, 45);
  double rx, ry;
  ASSERT_TRUE(c.world_to_raster({1, 0, 10}, rx, ry));
  EXPECT_GT(rx, 160);
  EXPECT_NEAR(ry, 120, 1e-9);
  ASSERT_TRUE(c.world_to_raster({0, 1, 10}, rx, ry));
  EXPECT_NEAR(rx, 160, 1e-9);
  EXPECT_LT(ry, 120) << "raster y grows downwards, so +y is above the centre";
}

TEST(Camera, FovSpansTheShorterAxis) {
  // Landscape: the vertical half-angle is fov/2, so a point at 45 degrees up with fov 90 is
  // on the top edge.
  Camera c = perspective_camera(400, 200, 90);
  double rx, ry;
  ASSERT_TRUE(c.world_to_raster({0, 1, 1}, rx, ry));
  EXPECT_NEAR(ry, 0, 1e-9);
  // Portrait: the horizontal axis is the shorter one.
  Camera p = perspective_camera(200, 400, 90);
  ASSERT_TRUE(p.world_to_raster({1, 0, 1}, rx, ry));
  EXPECT_NEAR(rx, 200, 1e-9);
}

TEST(Camera, RaysRoundTripThroughRaster) {
  Camera c = perspective_camera(320, 240, 30);
  c.world_to_camera = Matrix4::rotate(20, {0, 1, 0}) * Matrix4::translate({1, 2, 5});
  c.finalize();
  for (double x : {0.5, 100.25, 319.5})
    for (double y : {0.5, 77.0, 239.5}) {
      Ray r = c.generate_ray(x, y);
      EXPECT_NEAR(length(r.d), 1.0f, 1e-5f);
      double rx, ry;
      ASSERT_TRUE(c.world_to_raster(Vec3d(r.at(7.0f)), rx, ry));
      EXPECT_NEAR(rx, x, 1e-3);
      EXPECT_NEAR(ry, y, 1e-3);
    }
}

TEST(Camera, LensRaysMeetTheCentreRayOnTheFocalPlane) {
  // A thin lens of radius 0.2 focused at camera z = 4, under a camera transform with a scale:
  // every lens ray through a raster point meets the lens centre's ray where camera z = 4, and
  // lens_axes gives that distance along the centre ray and the lens radius in world units.
  Camera c = perspective_camera(320, 240, 30);
  c.world_to_camera = Matrix4::scale({2, 2, 2}) * Matrix4::rotate(20, {0, 1, 0}) * Matrix4::translate({1, 2, 5});
  c.finalize();
  c.lens_radius = 0.2;
  c.focal_distance = 4;
  ASSERT_TRUE(c.has_lens());
  for (double x : {0.5, 200.25})
    for (double y : {0.5, 120.0}) {
      const Ray centre = c.generate_ray(x, y);
      const Camera::LensAxes axes = c.lens_axes(x, y);
      const Vec3d focus = Vec3d(centre.at(axes.focus_t));
      EXPECT_NEAR(c.world_to_camera.transform_point(focus).z, 4, 1e-4);
      EXPECT_NEAR(length(axes.x_axis), 0.1f, 1e-6f) << "0.2 camera units are 0.1 world units";
      EXPECT_NEAR(dot(axes.x_axis, axes.y_axis), 0.0f, 1e-6f);
      for (auto [lx, ly] : {std::pair{1.0, 0.0}, std::pair{-0.3, 0.8}}) {
        const Ray lens = c.generate_lens_ray(x, y, lx, ly);
        EXPECT_NEAR(length(lens.d), 1.0f, 1e-5f);
        // Its origin is the lens point, its line passes through the focal point.
        const Vec3d o = c.world_to_camera.transform_point(Vec3d(lens.o));
        EXPECT_NEAR(o.x, 0.2 * lx, 1e-5);
        EXPECT_NEAR(o.y, 0.2 * ly, 1e-5);
        EXPECT_NEAR(o.z, 0, 1e-5);
        const Vec3d to_focus = focus - Vec3d(lens.o);
        EXPECT_NEAR(length(cross(to_focus, Vec3d(lens.d))), 0, 1e-4 * length(to_focus));
      }
    }
  // Without a lens the lens rays are the pinhole's.
  c.lens_radius = 0;
  const Ray a = c.generate_lens_ray(10, 20, 0.5, 0.5), b = c.generate_ray(10, 20);
  EXPECT_EQ(a.o, b.o);
  EXPECT_EQ(a.d, b.d);
}

TEST(Camera, OrthographicRaysAreParallelAlongPlusZ) {
  Camera c;
  c.xres = 200;
  c.yres = 100;
  c.screen = default_screen_window(2.0);
  c.finalize();
  Ray a = c.generate_ray(0, 0), b = c.generate_ray(200, 100);
  EXPECT_EQ(a.d, (Vec3f{0, 0, 1}));
  EXPECT_EQ(b.d, (Vec3f{0, 0, 1}));
  EXPECT_NEAR(a.o.x, -2, 1e-6);
  EXPECT_NEAR(a.o.y, 1, 1e-6);
  EXPECT_NEAR(b.o.x, 2, 1e-6);
  EXPECT_NEAR(b.o.y, -1, 1e-6);
}

TEST(Camera, ClippingPlanesLimitTheRay) {
  Camera c = perspective_camera(100, 100, 90);
  c.near_clip = 2;
  c.far_clip = 10;
  Ray r = c.camera_ray(0, 0);  // corner ray: z = t * d.z
  EXPECT_NEAR(r.tmin * r.d.z, 2, 1e-5);
  EXPECT_NEAR(r.tmax * r.d.z, 10, 1e-4);
}

TEST(Camera, DefaultScreenWindowFollowsTheAspect) {
  ScreenWindow l = default_screen_window(4.0 / 3.0);
  EXPECT_DOUBLE_EQ(l.left, -4.0 / 3.0);
  EXPECT_DOUBLE_EQ(l.top, 1);
  ScreenWindow p = default_screen_window(0.5);
  EXPECT_DOUBLE_EQ(p.right, 1);
  EXPECT_DOUBLE_EQ(p.top, 2);
}

TEST(Matrix, RotateFollowsTheRiConvention) {
  // RiRotate(90, 0, 1, 0) maps +x to -z (the same matrix pbrt and PRMan use).
  Vec3d p = Matrix4::rotate(90, {0, 1, 0}).transform_point({1, 0, 0});
  EXPECT_NEAR(p.x, 0, 1e-12);
  EXPECT_NEAR(p.z, -1, 1e-12);
  // ConcatTransform order: T * CTM applies T first.
  Matrix4 m = Matrix4::scale({2, 2, 2}) * Matrix4::translate({1, 0, 0});
  EXPECT_NEAR(m.transform_point({1, 0, 0}).x, 3, 1e-12);
  Matrix4 inv = m.inverse();
  EXPECT_NEAR(inv.transform_point({3, 0, 0}).x, 1, 1e-12);
}

}  // namespace
}  // namespace darc
