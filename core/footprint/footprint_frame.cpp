#include "core/footprint/footprint_frame.h"

#include <cmath>

namespace darc {

namespace {

bool finite(const Vec3d& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

bool FootprintFrame::make(const Ray& ray, const RayFootprint& footprint, FootprintFrame& out) {
  if (footprint.form == FootprintForm::General || !footprint.has_differentials()) return false;
  out.form = footprint.form;
  out.o = Vec3d(ray.o);
  out.d = Vec3d(ray.d);
  out.dox = Vec3d(footprint.dox);
  out.doy = Vec3d(footprint.doy);
  out.ddx = Vec3d(footprint.ddx);
  out.ddy = Vec3d(footprint.ddy);
  out.t_min = ray.tmin;
  out.t_max = ray.tmax;
  if (!finite(out.o) || !finite(out.d) || !finite(out.dox) || !finite(out.doy) || !finite(out.ddx) ||
      !finite(out.ddy) || std::isnan(out.t_min) || std::isnan(out.t_max))
    return false;
  if (out.form == FootprintForm::Pencil) {
    out.apex_t = footprint.apex_t;
    out.apex = out.o + out.d * out.apex_t;
    // The interval must not contain the apex (a camera ray starts there; a shadow ray ends at
    // its light).
    if (out.t_min >= out.apex_t) {
      out.side = 1;
    } else if (out.t_max <= out.apex_t) {
      out.side = -1;
    } else {
      return false;
    }
    for (int b = 0; b < kMaskSide * kMaskSide; ++b) out.point[size_t(b)] = out.direction(mask_point_u(b), mask_point_v(b));
    // Plane k through the apex and the sub-rays of one edge of the square; the inside is where
    // the centre sub-ray runs (after the apex for side +1, before it for side -1).
    const Vec3d inside = out.d * double(out.side);
    const Vec3d edge_dir[4] = {out.d - out.ddx * 0.5, out.d + out.ddx * 0.5, out.d - out.ddy * 0.5, out.d + out.ddy * 0.5};
    const Vec3d along[4] = {out.ddy, out.ddy, out.ddx, out.ddx};
    for (int k = 0; k < 4; ++k) {
      Vec3d n = cross(edge_dir[k], along[k]);
      if (dot(n, inside) < 0) n = -n;
      out.side_normal[size_t(k)] = n;
      out.side_point[size_t(k)] = out.apex;
    }
  } else {
    if (!(out.ddx == Vec3d{}) || !(out.ddy == Vec3d{})) return false;
    for (int b = 0; b < kMaskSide * kMaskSide; ++b) out.point[size_t(b)] = out.origin(mask_point_u(b), mask_point_v(b));
    // Plane k through one edge of the square of origins, along d; the inside holds the centre.
    const Vec3d edge_point[4] = {out.o - out.dox * 0.5, out.o + out.dox * 0.5, out.o - out.doy * 0.5, out.o + out.doy * 0.5};
    const Vec3d along[4] = {out.doy, out.doy, out.dox, out.dox};
    for (int k = 0; k < 4; ++k) {
      Vec3d n = cross(out.d, along[k]);
      if (dot(n, out.o - edge_point[k]) < 0) n = -n;
      out.side_normal[size_t(k)] = n;
      out.side_point[size_t(k)] = edge_point[k];
    }
  }
  return true;
}

bool FootprintFrame::outside_a_side(std::span<const Vec3f> corners) const {
  for (int k = 0; k < 4; ++k) {
    const Vec3d& n = side_normal[size_t(k)];
    const Vec3d& p = side_point[size_t(k)];
    bool all_outside = true;
    for (const Vec3f& c : corners)
      if (!(dot(n, Vec3d(c) - p) < 0)) {
        all_outside = false;
        break;
      }
    if (all_outside && !corners.empty()) return true;
  }
  return false;
}

}  // namespace darc
