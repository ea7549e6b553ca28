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
    out = {radiance_ * (area_ * cos_l / (d2 * kPi)), L, false, dist};
    return true;
  }

 protected:
  virtual Vec3f point(float u0, float u1) const = 0;
  virtual Vec3f centre() const = 0;

 private:
  Vec3f radiance_;
  int samples_;
  Vec3f normal_;
  float area_;
};

class RectLight : public FlatAreaLight {
 public:
  RectLight(const Vec3f& radiance, int samples, const Vec3f& corner, const Vec3f& ex, const Vec3f& ey,
            const Vec3f& normal)
      : FlatAreaLight(radiance, samples, normal, length(cross(ex, ey))), corner_(corner), ex_(ex), ey_(ey) {}

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
    out = {radiance_ * (2 * one_minus_cos_max), L, false, dist};
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
