#include "core/geometry/surfaces/dicing_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darc {

namespace {

// The largest factor by which m's linear part stretches a length (its largest singular value):
// power iteration on m^T m, whose Rayleigh quotient converges to it from below with an error
// quadratic in the iterate's; 1 % over it makes it a bound for what the iterations leave.
double largest_stretch(const Matrix4& m) {
  Vec3d x{0.57735, 0.57735, 0.57735};
  double sigma2 = 0;
  for (int i = 0; i < 64; ++i) {
    const Vec3d y = m.transform_vector(x);
    sigma2 = length_squared(y);  // x is a unit vector: |M x|^2 is the Rayleigh quotient of M^T M
    // M^T y: the row-vector convention transforms x as x M, so M^T y is y's dot with each row.
    const Vec3d back{m.m[0][0] * y.x + m.m[0][1] * y.y + m.m[0][2] * y.z,
                     m.m[1][0] * y.x + m.m[1][1] * y.y + m.m[1][2] * y.z,
                     m.m[2][0] * y.x + m.m[2][1] * y.y + m.m[2][2] * y.z};
    const double l = length(back);
    if (!(l > 0) || !std::isfinite(l)) break;
    x = back / l;
  }
  const double sigma = std::sqrt(sigma2) * 1.01;
  return sigma > 0 && std::isfinite(sigma) ? sigma : 1.0;
}

}  // namespace

double DicingView::pixel_size(const Vec3d& P) const {
  const Vec3d c = object_to_camera.transform_point(P);
  const double reach = perspective ? (c.z > 0 ? c.z : length(c)) : 1.0;
  return reach * pixel_span / stretch;
}

DicingView make_dicing_view(const Matrix4& object_to_world, const Matrix4& world_to_camera, bool perspective,
                            double fov_degrees, double screen_width, double screen_height, int xres, int yres) {
  DicingView v;
  v.object_to_camera = object_to_world * world_to_camera;
  v.perspective = perspective;
  // The screen window's [-1, 1] spans the field of view at distance 1 (perspective); it is
  // camera space itself for an orthographic camera.
  const double unit = perspective ? std::tan(fov_degrees * std::numbers::pi / 360.0) : 1.0;
  v.pixel_span = unit * std::min(std::abs(screen_width) / std::max(1, xres), std::abs(screen_height) / std::max(1, yres));
  v.stretch = largest_stretch(v.object_to_camera);
  return v;
}

}  // namespace darc
