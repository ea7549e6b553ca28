#include "shading/geometry_light.h"

#include "shading/area_lights.h"
#include "shading/shader_params.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace darc {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

class GeometryLight : public Light {
 public:
  struct Triangle {
    Vec3f a, e1, e2;
    Vec3f n;  // the side it emits to (unit)
  };
  struct Ball {
    Vec3f centre;
    float radius = 0;
    float outward = 1;  // -1: emits inward (Orientation "inside")
  };

  GeometryLight(Vec3f radiance, int samples) : radiance_(radiance), samples_(samples) {}
  void add(const Triangle& t) {
    const float area = 0.5f * length(cross(t.e1, t.e2));
    if (!(area > 0)) return;
    triangles_.push_back(t);
    add_area(area);
  }
  void add(const Ball& b) {
    const float area = 4 * kPi * b.radius * b.radius;
    if (!(area > 0)) return;
    // Balls come after every triangle in the cumulative areas.
    balls_.push_back(b);
    ball_areas_.push_back(area);
  }
  void finish() {
    for (float a : ball_areas_) add_area(a);
    total_ = cumulative_.empty() ? 0.0f : cumulative_.back();
  }
  bool empty() const { return cumulative_.empty(); }

  bool illuminate(const Vec3f&, LightContribution&, float) const override { return false; }
  int samples() const override { return empty() ? 0 : samples_; }
  bool sample(const Vec3f& P, float u0, float u1, LightContribution& out) const override {
    if (empty() || !(total_ > 0)) return false;
    // The piece by its area, and u0 stretched over that piece's share again.
    const float target = u0 * total_;
    const size_t i = std::min(size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin()),
                              cumulative_.size() - 1);
    const float lo = i == 0 ? 0.0f : cumulative_[i - 1], width = cumulative_[i] - lo;
    const float v = width > 0 ? std::clamp((target - lo) / width, 0.0f, 1.0f - 1e-7f) : 0.5f;
    Vec3f X, n;
    if (i < triangles_.size()) {
      const Triangle& t = triangles_[i];
      const float s = std::sqrt(v);  // uniform in the triangle
      X = t.a + t.e1 * (s * (1 - u1)) + t.e2 * (s * u1);
      n = t.n;
    } else {
      const Ball& b = balls_[i - triangles_.size()];
      const float z = 1 - 2 * v, r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = 2 * kPi * u1;
      const Vec3f dir{r * std::cos(phi), r * std::sin(phi), z};
      X = b.centre + dir * b.radius;
      n = dir * b.outward;
    }
    const Vec3f d = X - P;
    const float d2 = length_squared(d);
    if (!(d2 > 0)) return false;
    const float dist = std::sqrt(d2);
    const Vec3f L = d / dist;
    const float cos_l = -dot(n, L);
    if (!(cos_l > 0)) return false;
    out = {radiance_ * (total_ * cos_l / (d2 * kPi)), L, false, dist};
    return true;
  }

 private:
  void add_area(float a) { cumulative_.push_back((cumulative_.empty() ? 0.0f : cumulative_.back()) + a); }
  Vec3f radiance_;
  int samples_;
  std::vector<Triangle> triangles_;
  std::vector<Ball> balls_;
  std::vector<float> ball_areas_, cumulative_;
  float total_ = 0;
};

}  // namespace

std::unique_ptr<Light> make_geometry_light(const Scene& scene, uint32_t index, Diagnostics& diag) {
  const LightDesc& d = scene.lights.at(index);
  const Vec3f radiance = param_color(d.params, "lightcolor", {1, 1, 1}) * d.params.get_float("intensity", 1);
  const int samples = std::clamp(int(d.params.get_float("nsamples", float(kDefaultAreaLightSamples))), 1, 4096);
  auto light = std::make_unique<GeometryLight>(radiance, samples);
  const SurfaceSet& surfaces = scene.surfaces;
  bool skipped = false;
  for (uint32_t s = 0; s < surfaces.size(); ++s) {
    const Material& m = scene.materials[surfaces.material(s)];
    if (m.area_light != int(index)) continue;
    const float sign = m.flip_normals ? -1.0f : 1.0f;
    Vec3d centre;
    double radius;
    ConvexOutline outline;
    if (surfaces.whole_ball(s, centre, radius)) {
      light->add(GeometryLight::Ball{Vec3f(centre), float(radius), sign});
    } else if (surfaces.convex_outline(s, outline) && outline.count >= 3) {
      const Vec3f n = normalize(surfaces.geometric_normal(s, outline.corners[0])) * sign;
      for (int k = 1; k + 1 < outline.count; ++k)
        light->add(GeometryLight::Triangle{outline.corners[0], outline.corners[size_t(k)] - outline.corners[0],
                                           outline.corners[size_t(k + 1)] - outline.corners[0], n});
    } else {
      skipped = true;
    }
  }
  light->finish();
  if (skipped)
    diag.warning_once("arealight-shape:" + std::to_string(index), d.loc, "AreaLightSource",
                      "only whole spheres and planar convex pieces of an area light's geometry send light in darc: the "
                      "rest is drawn emissive and lights nothing");
  light->set_casts_shadows(d.casts_shadows);
  return light;
}

}  // namespace darc
