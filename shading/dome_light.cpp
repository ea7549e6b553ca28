#include "shading/dome_light.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace darc {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

Vec3f unit(const Vec3d& v) { return normalize(Vec3f(v)); }

class DomeLight : public Light {
 public:
  DomeLight(const Vec3f& radiance, int samples, const Matrix4& light_to_world, std::shared_ptr<const LatLongMap> map)
      : radiance_(radiance), samples_(samples), to_world_(light_to_world), to_dome_(light_to_world.inverse()),
        map_(std::move(map)) {}
  bool illuminate(const Vec3f&, LightContribution&, float) const override { return false; }
  int samples() const override { return samples_; }
  bool sample(const Vec3f& P, float u0, float u1, LightContribution& out) const override {
    return sample(P, Vec3f{}, u0, u1, out);
  }
  bool sample(const Vec3f&, const Vec3f& N, float u0, float u1, LightContribution& out) const override {
    const float inf = std::numeric_limits<float>::infinity();
    if (map_) {
      // Cl = L / (pi pdf): RI's diffuse() carries no 1/pi (shading/area_lights.h).
      LatLongMap::Sample s;
      if (!map_->sample(u0, u1, s)) return false;
      out = {mul(radiance_, s.radiance) * (1 / (kPi * s.pdf)), unit(to_world_.transform_vector(Vec3d(s.direction))), false,
             inf, s.pdf};
      return true;
    }
    const float phi = 2 * kPi * u1;
    if (length_squared(N) == 0.0f) {
      // Uniform over the sphere: pdf 1 / (4 pi), so the sample stands for 4 pi steradians.
      const float z = 1 - 2 * u0, r = std::sqrt(std::max(0.0f, 1 - z * z));
      out = {radiance_ * 4.0f, Vec3f{r * std::cos(phi), r * std::sin(phi), z}, false, inf, 1 / (4 * kPi)};
      return true;
    }
    // By the cosine about N (Malley): pdf cos / pi, so the sample stands for pi / cos.
    const float cos_t = std::sqrt(std::max(0.0f, 1 - u0)), sin_t = std::sqrt(std::max(0.0f, u0));
    if (!(cos_t > 1e-6f)) return false;
    const Vec3f a = normalize(std::abs(N.x) < 0.9f ? cross(N, Vec3f{1, 0, 0}) : cross(N, Vec3f{0, 1, 0}));
    const Vec3f b = cross(N, a);
    const Vec3f L = normalize(N * cos_t + a * (sin_t * std::cos(phi)) + b * (sin_t * std::sin(phi)));
    out = {radiance_ * (1 / cos_t), L, false, inf, cos_t / kPi};
    return true;
  }
  bool can_be_hit() const override { return true; }
  bool has_constant_radiance() const override { return !map_; }
  bool hit(const Vec3f&, const Vec3f& N, const Vec3f& L, LightHit& out) const override {
    out.distance = std::numeric_limits<float>::infinity();
    out.radiance = environment(L);
    if (map_) out.pdf = map_->pdf(unit(to_dome_.transform_vector(Vec3d(L))));
    else if (length_squared(N) == 0.0f) out.pdf = 1 / (4 * kPi);
    else out.pdf = std::max(0.0f, dot(N, L)) / kPi;
    return true;
  }
  Vec3f environment(const Vec3f& d) const override {
    if (!map_) return radiance_;
    return mul(radiance_, map_->radiance(unit(to_dome_.transform_vector(Vec3d(d)))));
  }

 private:
  Vec3f radiance_;
  int samples_;
  Matrix4 to_world_, to_dome_;
  std::shared_ptr<const LatLongMap> map_;
};

}  // namespace

std::unique_ptr<Light> make_dome_light(const Vec3f& radiance, int samples, const Matrix4& light_to_world,
                                       std::shared_ptr<const LatLongMap> map) {
  return std::make_unique<DomeLight>(radiance, std::max(samples, 1), light_to_world, std::move(map));
}

}  // namespace darc
