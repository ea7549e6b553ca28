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
  } else {
    if (!(out.ddx == Vec3d{}) || !(out.ddy == Vec3d{})) return false;
    for (int b = 0; b < kMaskSide * kMaskSide; ++b) out.point[size_t(b)] = out.origin(mask_point_u(b), mask_point_v(b));
  }
  return true;
}

}  // namespace darc
