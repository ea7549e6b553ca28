#include "shading/area_lights.h"

#include "core/math/concentric_disc.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace darc {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// A flat shape: a point at (u, v) in [0, 1)^2 with the area it stands for, its unit normal (the
// lit side) and its area.
class FlatAreaLight : public Light {
 public:
  FlatAreaLight(const Vec3f& radiance, int samples, const Vec3f& normal, float area)
      : radiance_(radiance), samples_(samples), normal_(normal), area_(area) {}
  bool illuminate(const Vec3f&, LightContribution&, float) const override { return false; }
  int samples() const override { return samples_; }
  // The shape's centre; the disc of its area foreshortened as P sees it.
  bool extent_toward(const Vec3f& P, LightExtent& out) const override {
    const Vec3f d = centre() - P;
    const float dist = length(d);
    if (!(dist > 0) || !(area_ > 0)) return false;
    out.L = d / dist;
    const float cos_l = -dot(normal_, out.L);
    if (!(cos_l > 0)) return false;
    out.distance = dist;
    out.half_angle = std::atan(std::sqrt(area_ * cos_l / kPi) / dist);
    return true;
  }
  bool sample(const Vec3f& P, float u0, float u1, LightContribution& out) const override {
    const Vec3f X = point(u0, u1);
    const Vec3f d = X - P;
    const float d2 = length_squared(d);
    if (!(d2 > 0) || !(area_ > 0)) return false;
    const float dist = std::sqrt(d2);
    const Vec3f L = d / dist;
    const float cos_l = -dot(normal_, L);  // the light's side faces P
    if (!(cos_l > 0)) return false;
    // By area: the sample stands for a solid angle area * cos_l / d^2.
    out = {radiance_ * (area_ * cos_l / (d2 * kPi)), L, false, dist, d2 / (area_ * cos_l)};
    return true;
  }
  bool can_be_hit() const override { return true; }
  // The plane of the shape, seen from its lit side, then the shape itself.
  bool hit(const Vec3f& P, const Vec3f&, const Vec3f& L, LightHit& out) const override {
    const float cos_l = -dot(normal_, L);
    if (!(cos_l > 0) || !(area_ > 0)) return false;
    const float t = dot(centre() - P, normal_) / -cos_l;
    if (!(t > 0) || !std::isfinite(t) || !on_shape(P + L * t)) return false;
    out.distance = t;
    out.radiance = radiance_;
    out.pdf = pdf_toward(P, t, cos_l);
    return true;
  }

 protected:
  virtual Vec3f point(float u0, float u1) const = 0;
  virtual Vec3f centre() const = 0;
  // Whether a point of the shape's plane lies on the shape.
  virtual bool on_shape(const Vec3f& X) const = 0;
  // The density sample() draws a direction with that meets the shape `dist` away at cosine cos_l.
  virtual float pdf_toward(const Vec3f& /*P*/, float dist, float cos_l) const { return dist * dist / (area_ * cos_l); }
  // (u, v) of X - origin in the basis (e, f) of the plane (a parallelogram's own coordinates).
  static void plane_coordinates(const Vec3f& d, const Vec3f& e, const Vec3f& f, float& u, float& v) {
    const Vec3f n = cross(e, f);
    const float n2 = length_squared(n);
    u = dot(cross(d, f), n) / n2;
    v = dot(cross(e, d), n) / n2;
  }

  Vec3f radiance_;
  int samples_;
  Vec3f normal_;
  float area_;
};

// Spherical rectangles (Urena, Fajardo, King, "An Area-Preserving Parametrization for Spherical
// Rectangles", EGSR 2013): (u0, u1) in [0, 1)^2 onto the rectangle's points so that equal areas
// of the square are equal solid angles seen from P. Sampled by area, a receiver close to a large
// light gets samples whose solid angles differ by orders of magnitude (area cos / d^2); sampled
// by solid angle each stands for the same, and only the receiver's cosine varies. Below this
// solid angle (steradians) the light is sampled by area: the two agree there within rounding,
// and S, a difference of angles near 2 pi, loses its digits (pbrt-v4 switches at 3e-4 for its
// spherical triangles and rectangles).
constexpr double kMinSphericalSolidAngle = 1e-3;
// Edges farther from perpendicular than this (cosine) make a parallelogram (a sheared light), which
// the parametrization does not cover: sampled by area.
constexpr double kMaxEdgeCosine = 1e-4;

class RectLight : public FlatAreaLight {
  // The rectangle as P sees it: a frame along its edges (z toward P's side negative, z0 < 0), the
  // corners' coordinates, and the solid angle with the constants the sampling inverts.
  struct SphericalRect {
    Vec3d x, y, z;
    double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, b0 = 0, b1 = 0, k = 0, solid_angle = 0;
    bool behind = false;  // P on the unlit side: nothing
  };
  // False where the light is sampled by area instead (sheared, or under kMinSphericalSolidAngle),
  // or not at all (r.behind).
  bool spherical_rect(const Vec3f& P, SphericalRect& r) const {
    const Vec3d o(P), s(corner_), exd(ex_), eyd(ey_);
    const double lx = length(exd), ly = length(eyd);
    if (!(lx > 0) || !(ly > 0) || std::abs(dot(exd, eyd)) > kMaxEdgeCosine * lx * ly) return false;
    // Only the lit side sees the light (the plane is seen from one side by all of it).
    if (!(dot(Vec3d(normal_), o - (s + (exd + eyd) * 0.5)) > 0)) {
      r.behind = true;
      return false;
    }
    r.x = exd / lx;
    r.y = eyd / ly;
    r.z = cross(r.x, r.y);
    const Vec3d d = s - o;
    r.z0 = dot(d, r.z);
    if (r.z0 > 0) r.z = -r.z, r.z0 = -r.z0;
    r.x0 = dot(d, r.x), r.y0 = dot(d, r.y), r.x1 = r.x0 + lx, r.y1 = r.y0 + ly;
    const Vec3d v00{r.x0, r.y0, r.z0}, v01{r.x0, r.y1, r.z0}, v10{r.x1, r.y0, r.z0}, v11{r.x1, r.y1, r.z0};
    const Vec3d n0 = normalize(cross(v00, v10)), n1 = normalize(cross(v10, v11)), n2 = normalize(cross(v11, v01)),
                n3 = normalize(cross(v01, v00));
    auto angle = [](const Vec3d& a, const Vec3d& b) { return std::acos(std::clamp(-dot(a, b), -1.0, 1.0)); };
    const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    r.b0 = n0.z, r.b1 = n2.z, r.k = 2 * std::numbers::pi - g2 - g3;
    r.solid_angle = g0 + g1 - r.k;
    return r.solid_angle >= kMinSphericalSolidAngle && std::isfinite(r.solid_angle);
  }

 public:
  RectLight(const Vec3f& radiance, int samples, const Vec3f& corner, const Vec3f& ex, const Vec3f& ey,
            const Vec3f& normal)
      : FlatAreaLight(radiance, samples, normal, length(cross(ex, ey))),
        corner_(corner),
        ex_(ex),
        ey_(ey) {}

  bool sample(const Vec3f& P, float u0, float u1, LightContribution& out) const override {
    SphericalRect r;
    if (!spherical_rect(P, r)) {
      if (r.behind) return false;
      return FlatAreaLight::sample(P, u0, u1, out);
    }
    // u0 picks the solid angle to the left of a plane through P and the line x = xu; u1 the
    // height along that line, uniform in the sine of its elevation.
    const double au = double(u0) * r.solid_angle + r.k;
    const double fu = (std::cos(au) * r.b0 - r.b1) / std::sin(au);
    double cu = std::copysign(1.0, fu) / std::sqrt(fu * fu + r.b0 * r.b0);
    cu = std::clamp(cu, -1.0, 1.0);
    double xu = -(cu * r.z0) / std::max(std::sqrt(1 - cu * cu), 1e-300);
    xu = std::clamp(std::isfinite(xu) ? xu : (cu > 0 ? r.x1 : r.x0), r.x0, r.x1);
    const double dist_xz = std::sqrt(xu * xu + r.z0 * r.z0);
    const double h0 = r.y0 / std::sqrt(dist_xz * dist_xz + r.y0 * r.y0),
                 h1 = r.y1 / std::sqrt(dist_xz * dist_xz + r.y1 * r.y1);
    const double hv = h0 + double(u1) * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1 - 1e-12 ? std::clamp(hv * dist_xz / std::sqrt(1 - hv2), r.y0, r.y1) : r.y1;
    const Vec3d to_point = r.x * xu + r.y * yv + r.z * r.z0;
    const double dist = length(to_point);
    if (!(dist > 0) || !std::isfinite(dist)) return FlatAreaLight::sample(P, u0, u1, out);
    // Each sample stands for the same solid angle.
    out = {radiance_ * float(r.solid_angle / std::numbers::pi), Vec3f(to_point / dist), false, float(dist),
           float(1 / r.solid_angle)};
    return true;
  }

 protected:
  bool on_shape(const Vec3f& X) const override {
    float u, v;
    plane_coordinates(X - corner_, ex_, ey_, u, v);
    return u >= 0 && u <= 1 && v >= 0 && v <= 1;
  }
  float pdf_toward(const Vec3f& P, float dist, float cos_l) const override {
    SphericalRect r;
    return spherical_rect(P, r) ? float(1 / r.solid_angle) : FlatAreaLight::pdf_toward(P, dist, cos_l);
  }

 protected:
  Vec3f point(float u0, float u1) const override { return corner_ + ex_ * u0 + ey_ * u1; }
  Vec3f centre() const override { return corner_ + (ex_ + ey_) * 0.5f; }

 private:
  Vec3f corner_, ex_, ey_;
};

class DiskLight : public FlatAreaLight {
 public:
  // The disc (an ellipse under a non-uniform scale) centre + a cos t + b sin t.
  DiskLight(const Vec3f& radiance, int samples, const Vec3f& centre, const Vec3f& a, const Vec3f& b, const Vec3f& normal)
      : FlatAreaLight(radiance, samples, normal, kPi * length(cross(a, b))), centre_(centre), a_(a), b_(b) {}

 protected:
  // Shirley and Chiu's concentric map of the square onto the disc.
  Vec3f point(float u0, float u1) const override {
    const Vec2f p = concentric_disc(u0, u1);
    return centre_ + a_ * p.x + b_ * p.y;
  }
  Vec3f centre() const override { return centre_; }
  bool on_shape(const Vec3f& X) const override {
    float u, v;
    plane_coordinates(X - centre_, a_, b_, u, v);
    return u * u + v * v <= 1;
  }

 private:
  Vec3f centre_, a_, b_;
};

class SphereLight : public Light {
 public:
  SphereLight(const Vec3f& radiance, int samples, const Vec3f& centre, float radius)
      : radiance_(radiance), samples_(samples), centre_(centre), radius_(radius) {}
  bool illuminate(const Vec3f&, LightContribution&, float) const override { return false; }
  int samples() const override { return samples_; }
  // The cone the sphere subtends; the shadow ray ends on its near side.
  bool extent_toward(const Vec3f& P, LightExtent& out) const override {
    const Vec3f to_centre = centre_ - P;
    const float d = length(to_centre);
    if (!(d > radius_)) return false;
    out.L = to_centre / d;
    out.distance = d - radius_;
    out.half_angle = std::asin(radius_ / d);
    return true;
  }
  bool sample(const Vec3f& P, float u0, float u1, LightContribution& out) const override {
    const Vec3f to_centre = centre_ - P;
    const float d2 = length_squared(to_centre);
    const float r2 = radius_ * radius_;
    if (!(d2 > r2)) return false;  // inside the light (or a degenerate one): nothing sampled
    const float dist_c = std::sqrt(d2);
    const Vec3f w = to_centre / dist_c;
    // Uniform in the cone of half-angle theta_max (sin = r / d): 1 - cos theta_max from
    // sin^2 / (1 + cos) keeps precision for small lights (pbrt-v4's Sphere::Sample does the same
    // below 1.5 degrees).
    const float sin2_max = r2 / d2;
    const float cos_max = std::sqrt(std::max(0.0f, 1 - sin2_max));
    const float one_minus_cos_max = sin2_max / (1 + cos_max);
    const float one_minus_cos = u0 * one_minus_cos_max;
    const float cos_t = 1 - one_minus_cos;
    const float sin_t = std::sqrt(std::max(0.0f, one_minus_cos * (2 - one_minus_cos)));
    const float phi = 2 * kPi * u1;
    const Vec3f a = normalize(std::abs(w.x) < 0.9f ? cross(w, Vec3f{1, 0, 0}) : cross(w, Vec3f{0, 1, 0}));
    const Vec3f b = cross(w, a);
    const Vec3f L = normalize(w * cos_t + a * (sin_t * std::cos(phi)) + b * (sin_t * std::sin(phi)));
    // Where the direction meets the sphere (its near side): the shadow ray ends there.
    const float along = dot(to_centre, L);
    const float h2 = std::max(0.0f, r2 - (d2 - along * along));
    const float dist = std::max(0.0f, along - std::sqrt(h2));
    // The sample stands for the cone's solid angle 2 pi (1 - cos theta_max).
    out = {radiance_ * (2 * one_minus_cos_max), L, false, dist, 1 / (2 * kPi * one_minus_cos_max)};
    return true;
  }
  bool can_be_hit() const override { return true; }
  // The near side of the sphere; the density of the uniform cone.
  bool hit(const Vec3f& P, const Vec3f&, const Vec3f& L, LightHit& out) const override {
    const Vec3f to_centre = centre_ - P;
    const float d2 = length_squared(to_centre), r2 = radius_ * radius_;
    if (!(d2 > r2)) return false;
    const float along = dot(to_centre, L);
    const float h2 = r2 - (d2 - along * along);
    if (!(along > 0) || !(h2 >= 0)) return false;
    const float sin2_max = r2 / d2;
    const float one_minus_cos_max = sin2_max / (1 + std::sqrt(std::max(0.0f, 1 - sin2_max)));
    out.distance = std::max(0.0f, along - std::sqrt(h2));
    out.radiance = radiance_;
    out.pdf = 1 / (2 * kPi * one_minus_cos_max);
    return true;
  }

 private:
  Vec3f radiance_;
  int samples_;
  Vec3f centre_;
  float radius_;
};

Vec3f to_f(const Vec3d& v) { return Vec3f(v); }

}  // namespace

bool area_shape_of(const std::string& shader, AreaShape& shape) {
  if (shader == "rectlight") shape = AreaShape::Rect;
  else if (shader == "disklight") shape = AreaShape::Disk;
  else if (shader == "spherelight") shape = AreaShape::Sphere;
  else return false;
  return true;
}

std::unique_ptr<Light> make_area_light(AreaShape shape, const Matrix4& m, const Vec3f& radiance, int samples) {
  samples = std::max(samples, 1);
  const Vec3f origin = to_f(m.transform_point({0, 0, 0}));
  const Vec3f ex = to_f(m.transform_vector({1, 0, 0})), ey = to_f(m.transform_vector({0, 1, 0}));
  const Vec3f ez = to_f(m.transform_vector({0, 0, 1}));
  // The lit side: the plane's normal on the side its own +z goes to.
  Vec3f normal = normalize(cross(ex, ey));
  if (dot(normal, ez) < 0) normal = -normal;
  switch (shape) {
    case AreaShape::Rect:
      return std::make_unique<RectLight>(radiance, samples, origin - ex * 0.5f - ey * 0.5f, ex, ey, normal);
    case AreaShape::Disk:
      return std::make_unique<DiskLight>(radiance, samples, origin, ex * 0.5f, ey * 0.5f, normal);
    case AreaShape::Sphere:
      return std::make_unique<SphereLight>(radiance, samples, origin,
                                           float(0.5 * std::cbrt(std::fabs(m.determinant()))));
  }
  return nullptr;
}

}  // namespace darc
