// The RenderMan camera: camera space is left-handed, looking down +z, x right, y up.
// Raster space has (0,0) at the top-left corner of the image; pixel (i,j) covers [i,i+1)x[j,j+1).
#pragma once

#include "core/math/matrix.h"
#include "core/math/ray.h"

namespace darc {

struct ScreenWindow {
  double left = -1, right = 1, bottom = -1, top = 1;
};

struct Camera {
  enum class Projection { Orthographic, Perspective };

  Projection projection = Projection::Orthographic;
  double fov_degrees = 90;  // perspective only; spans the screen window's [-1, 1] range
  ScreenWindow screen;
  int xres = 640, yres = 480;
  double near_clip = 1e-10, far_clip = 1e38;
  Matrix4 world_to_camera;
  Matrix4 camera_to_world;
  // A thin lens (RI DepthOfField, modelled as pbrt-v4's perspective camera): a disc of this
  // radius on the plane z = 0 of camera space, focused on the plane z = focal_distance. A radius
  // of 0 is a pinhole (RI's default fstop of infinity).
  double lens_radius = 0;
  double focal_distance = 1;

  // Sets camera_to_world from world_to_camera.
  void finalize() { camera_to_world = world_to_camera.inverse(); }

  // Screen-space position of a continuous raster position.
  void raster_to_screen(double rx, double ry, double& sx, double& sy) const;
  // Camera-space ray through a raster position (unit direction for perspective, +z for orthographic),
  // clipped to [near, far] along camera z.
  Ray camera_ray(double rx, double ry) const;
  // World-space ray (unit direction) through a raster position (the lens centre's ray).
  Ray generate_ray(double rx, double ry) const;
  // World-space ray through a raster position from the lens point (lens_x, lens_y) of the unit
  // disc (scaled by lens_radius): it meets the lens centre's ray on the focal plane.
  Ray generate_lens_ray(double rx, double ry, double lens_x, double lens_y) const;
  bool has_lens() const { return lens_radius > 0; }
  // The lens as world-space vectors, for footprints: the lens disc's radius along camera x and
  // y (`x_axis`, `y_axis`) and the distance along the lens centre's ray `ray` (unit direction,
  // from generate_ray) at which it meets the focal plane.
  struct LensAxes {
    Vec3f x_axis, y_axis;
    float focus_t = 0;
  };
  LensAxes lens_axes(double rx, double ry) const;
  // Projects a world-space point to raster coordinates; returns false when behind the camera.
  bool world_to_raster(const Vec3d& p, double& rx, double& ry) const;
};

// The RI default screen window for a frame aspect ratio (xres * pixel aspect / yres):
// (-a, a, -1, 1) when a >= 1, else (-1, 1, -1/a, 1/a).
ScreenWindow default_screen_window(double frame_aspect);

}  // namespace darc
