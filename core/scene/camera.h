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

  // Sets camera_to_world from world_to_camera.
  void finalize() { camera_to_world = world_to_camera.inverse(); }

  // Screen-space position of a continuous raster position.
  void raster_to_screen(double rx, double ry, double& sx, double& sy) const;
  // Camera-space ray through a raster position (unit direction for perspective, +z for orthographic),
  // clipped to [near, far] along camera z.
  Ray camera_ray(double rx, double ry) const;
  // World-space ray (unit direction) through a raster position.
  Ray generate_ray(double rx, double ry) const;
  // Projects a world-space point to raster coordinates; returns false when behind the camera.
  bool world_to_raster(const Vec3d& p, double& rx, double& ry) const;
};

// The RI default screen window for a frame aspect ratio (xres * pixel aspect / yres):
// (-a, a, -1, 1) when a >= 1, else (-1, 1, -1/a, 1/a).
ScreenWindow default_screen_window(double frame_aspect);

}  // namespace darc
