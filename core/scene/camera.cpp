#include "core/scene/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace darc {

ScreenWindow default_screen_window(double a) {
  if (!(a > 0)) a = 1;
  if (a >= 1) return {-a, a, -1, 1};
  return {-1, 1, -1 / a, 1 / a};
}

void Camera::raster_to_screen(double rx, double ry, double& sx, double& sy) const {
  sx = screen.left + (screen.right - screen.left) * (rx / xres);
  sy = screen.top - (screen.top - screen.bottom) * (ry / yres);  // raster y goes down
}

Ray Camera::camera_ray(double rx, double ry) const {
  double sx, sy;
  raster_to_screen(rx, ry, sx, sy);
  Vec3d o, d;
  if (projection == Projection::Perspective) {
    // The screen plane sits at distance 1/tan(fov/2), so screen +-1 spans the field of view.
    double tan_half = std::tan(fov_degrees * std::numbers::pi / 360.0);
    d = normalize(Vec3d{sx * tan_half, sy * tan_half, 1.0});
  } else {
    o = {sx, sy, 0};
    d = {0, 0, 1};
  }
  Ray r;
  r.o = Vec3f(o);
  r.d = Vec3f(d);
  // Clipping planes are planes of constant camera z.
  r.tmin = float(std::max(0.0, (near_clip - o.z) / d.z));
  r.tmax = float(std::min(double(std::numeric_limits<float>::max()), (far_clip - o.z) / d.z));
  return r;
}

Ray Camera::generate_ray(double rx, double ry) const {
  Ray c = camera_ray(rx, ry);
  Ray w;
  w.o = Vec3f(camera_to_world.transform_point(Vec3d(c.o)));
  Vec3d d = camera_to_world.transform_vector(Vec3d(c.d));
  double len = length(d);
  w.d = Vec3f(d / len);
  // Keep t a world-space distance.
  w.tmin = float(c.tmin * len);
  w.tmax = float(std::min(double(std::numeric_limits<float>::max()), double(c.tmax) * len));
  return w;
}

Ray Camera::generate_lens_ray(double rx, double ry, double lens_x, double lens_y) const {
  if (!has_lens()) return generate_ray(rx, ry);
  Ray c = camera_ray(rx, ry);
  // The pinhole ray meets the focal plane z = focal_distance at F; the lens ray runs from the
  // lens point to F (pbrt-v4's thin lens).
  const Vec3d o(c.o), d(c.d);
  const Vec3d focus = o + d * ((focal_distance - o.z) / d.z);
  const Vec3d lens_o = o + Vec3d{lens_x * lens_radius, lens_y * lens_radius, 0};
  const Vec3d dir = normalize(focus - lens_o);
  Ray w;
  w.o = Vec3f(camera_to_world.transform_point(lens_o));
  Vec3d wd = camera_to_world.transform_vector(dir);
  const double len = length(wd);
  w.d = Vec3f(wd / len);
  // Clipping planes are planes of constant camera z; t stays a world-space distance.
  w.tmin = float(std::max(0.0, near_clip / dir.z) * len);
  w.tmax = float(std::min(double(std::numeric_limits<float>::max()), far_clip / dir.z * len));
  return w;
}

Camera::LensAxes Camera::lens_axes(double rx, double ry) const {
  LensAxes axes;
  if (!has_lens()) return axes;
  Ray c = camera_ray(rx, ry);
  const Vec3d o(c.o), d(c.d);
  const double camera_t = (focal_distance - o.z) / d.z;  // along the unit camera-space direction
  const double len = length(camera_to_world.transform_vector(d));
  axes.x_axis = Vec3f(camera_to_world.transform_vector(Vec3d{lens_radius, 0, 0}));
  axes.y_axis = Vec3f(camera_to_world.transform_vector(Vec3d{0, lens_radius, 0}));
  axes.focus_t = float(camera_t * len);
  return axes;
}

bool Camera::world_to_raster(const Vec3d& p, double& rx, double& ry) const {
  Vec3d c = world_to_camera.transform_point(p);
  double sx = c.x, sy = c.y;
  if (projection == Projection::Perspective) {
    if (c.z <= 0) return false;
    double tan_half = std::tan(fov_degrees * std::numbers::pi / 360.0);
    sx = c.x / (c.z * tan_half);
    sy = c.y / (c.z * tan_half);
  }
  rx = (sx - screen.left) / (screen.right - screen.left) * xres;
  ry = (screen.top - sy) / (screen.top - screen.bottom) * yres;
  return true;
}

}  // namespace darc
