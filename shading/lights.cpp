#include "shading/lights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/scene/builder/shader_parameter_checks.h"
#include "shading/area_lights.h"
#include "shading/dome_light.h"
#include "shading/shader_params.h"

namespace darc {

namespace {

Vec3d param_point(const ParamList& p, const char* name, Vec3d fallback) {
  const Param* x = p.find(name);
  if (!x || x->floats.size() < 3) return fallback;
  return {x->floats[0], x->floats[1], x->floats[2]};
}

// The dome's lat-long map: "mapname" (what PxrDomeLight's lightColorMap becomes), or "envname"
// as some environment light shaders call it; the scene builder made it a full path, or cleared it
// when the file was not found.
std::string dome_map_name(const ParamList& p) {
  for (const char* name : {"mapname", "envname"})
    if (const Param* x = p.find(name); x && x->decl.is_string() && !x->strings.empty() && !x->strings[0].empty())
      return x->strings[0];
  return {};
}

class NoLight : public Light {
 public:
  bool illuminate(const Vec3f&, LightContribution&, float) const override { return false; }
};

class AmbientLight : public Light {
 public:
  explicit AmbientLight(Vec3f c) : c_(c) {}
  bool illuminate(const Vec3f&, LightContribution& out, float) const override {
    out = {c_, {}, true, 0};
    return true;
  }

 private:
  Vec3f c_;
};

// A distant light, with an angular diameter (distantlight's "angle", degrees; PxrDistantLight's
// angleExtent: the sun's is 0.53) or none. With one it is sampled: directions uniform in the cone
// it subtends, each carrying the light's whole irradiance (the caller averages), so that a surface
// facing it gets what the delta light gives and shadows soften over the cone, as RenderMan's.
class DistantLight : public Light {
 public:
  DistantLight(Vec3f c, Vec3f dir, float angle_degrees, int samples)
      : c_(c), to_light_(-normalize(dir)), samples_(samples) {
    const float half = 0.5f * std::clamp(angle_degrees, 0.0f, 90.0f) * std::numbers::pi_v<float> / 180.0f;
    half_angle_ = length_squared(to_light_) > 0 ? half : 0.0f;
    const float s = std::sin(half);
    one_minus_cos_max_ = s * s / (1 + std::cos(half));  // 1 - cos, precise for small angles
  }
  bool illuminate(const Vec3f&, LightContribution& out, float) const override {
    out = {c_, to_light_, false, std::numeric_limits<float>::infinity()};
    return length_squared(to_light_) > 0;
  }
  int samples() const override { return one_minus_cos_max_ > 0 && length_squared(to_light_) > 0 ? samples_ : 0; }
  float cone_half_angle() const override { return half_angle_; }
  bool sample(const Vec3f&, float u0, float u1, LightContribution& out) const override {
    const Vec3f& w = to_light_;
    const float one_minus_cos = u0 * one_minus_cos_max_;
    const float cos_t = 1 - one_minus_cos;
    const float sin_t = std::sqrt(std::max(0.0f, one_minus_cos * (2 - one_minus_cos)));
    const float phi = 2 * std::numbers::pi_v<float> * u1;
    const Vec3f a = normalize(std::abs(w.x) < 0.9f ? cross(w, Vec3f{1, 0, 0}) : cross(w, Vec3f{0, 1, 0}));
    const Vec3f b = cross(w, a);
    const Vec3f L = normalize(w * cos_t + a * (sin_t * std::cos(phi)) + b * (sin_t * std::sin(phi)));
    out = {c_, L, false, std::numeric_limits<float>::infinity()};
    return true;
  }

 private:
  Vec3f c_, to_light_;
  int samples_;
  float half_angle_ = 0;
  float one_minus_cos_max_ = 0;
};

class PointLight : public Light {
 public:
  PointLight(Vec3f c, Vec3f from) : c_(c), from_(from) {}
  bool illuminate(const Vec3f& P, LightContribution& out, float) const override {
    Vec3f d = from_ - P;
    float d2 = length_squared(d);
    if (!(d2 > 0)) return false;
    float dist = std::sqrt(d2);
    out = {c_ / d2, d / dist, false, dist};  // inverse-square falloff, as pointlight.sl
    return true;
  }

 private:
  Vec3f c_, from_;
};

class SpotLight : public Light {
 public:
  SpotLight(Vec3f c, Vec3f from, Vec3f axis, float cone, float delta, float beam)
      : c_(c), from_(from), axis_(normalize(axis)), cos_outside_(std::cos(cone)),
        cos_inside_(std::cos(cone - delta)), beam_(beam) {}
  bool illuminate(const Vec3f& P, LightContribution& out, float footprint_radius) const override {
    Vec3f d = from_ - P;
    float d2 = length_squared(d);
    if (!(d2 > 0)) return false;
    float dist = std::sqrt(d2);
    Vec3f L = d / dist;
    float cosangle = dot(-L, axis_);
    // The cone's edge seen through the footprint: the footprint spans an angle of about
    // 2 footprint_radius / dist around L, so cos(angle) varies by sin(angle) times that over it;
    // an edge sharper than that becomes a ramp as wide (the box-filtered step).
    float outside = cos_outside_, inside = cos_inside_;
    const float spread = std::sqrt(std::max(0.0f, 1 - cosangle * cosangle)) * footprint_radius / dist;
    if (spread > 0 && inside - outside < 2 * spread) {
      const float mid = 0.5f * (outside + inside);
      outside = mid - spread;
      inside = mid + spread;
    }
    if (cosangle <= outside) return false;
    float atten = std::pow(std::max(cosangle, 0.0f), beam_) / d2;
    atten *= smoothstep(outside, inside, cosangle);
    out = {c_ * atten, L, false, dist};
    return atten > 0;
  }

 private:
  static float smoothstep(float a, float b, float x) {
    if (a >= b) return x >= b ? 1.0f : 0.0f;
    float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
  }
  Vec3f c_, from_, axis_;
  float cos_outside_, cos_inside_, beam_;
};

}  // namespace

std::vector<std::unique_ptr<Light>> make_lights(const std::vector<LightDesc>& descs, Diagnostics& diag) {
  std::vector<std::unique_ptr<Light>> lights;
  for (const LightDesc& d : descs) {
    const ParamList& p = d.params;
    float intensity = p.get_float("intensity", 1.0f);
    Vec3f c = param_color(p, "lightcolor", {1, 1, 1}) * intensity;
    Vec3d from = param_point(p, "from", {0, 0, 0});
    Vec3d to = param_point(p, "to", {0, 0, 1});
    Vec3f from_w = Vec3f(d.shader_to_world.transform_point(from));
    Vec3f to_w = Vec3f(d.shader_to_world.transform_point(to));
    std::string kind = d.shader;
    if (d.geometry) {
      // An AreaLightSource: its shape is scene geometry (shading/geometry_light.h, which
      // SceneShading makes); alone it sends nothing.
      lights.push_back(std::make_unique<NoLight>());
      continue;
    }
    AreaShape shape;
    if (kind == "domelight" || kind == "envlight") {
      const int samples = int(p.get_float("nsamples", float(kDefaultAreaLightSamples)));
      std::shared_ptr<const LatLongMap> map;
      if (const std::string name = dome_map_name(p); !name.empty()) {
        std::string reason;
        if (auto loaded = LatLongMap::load(name, reason))
          map = std::make_shared<const LatLongMap>(std::move(*loaded));
        else
          diag.warning_once("dome-map:" + name, d.loc, "LightSource",
                            "environment map \"" + name + "\" cannot be read (" + reason +
                                "): the dome lights with its colour alone");
      }
      lights.push_back(make_dome_light(c, std::clamp(samples, 1, 4096), d.shader_to_world, std::move(map)));
      lights.back()->set_casts_shadows(d.casts_shadows);
      continue;
    }
    if (area_shape_of(kind, shape)) {
      const int samples = int(p.get_float("nsamples", float(kDefaultAreaLightSamples)));
      lights.push_back(make_area_light(shape, d.shader_to_world, c, std::clamp(samples, 1, 4096)));
      lights.back()->set_casts_shadows(d.casts_shadows);
      continue;
    }
    if (kind == "shadowspot") kind = "spotlight";
    if (kind == "shadowpoint") kind = "pointlight";
    if (kind == "shadowdistant") kind = "distantlight";
    if (kind != "ambientlight" && kind != "distantlight" && kind != "pointlight" && kind != "spotlight") {
      std::string fallback = (p.find("to") && p.find("coneangle")) ? "spotlight"
                             : p.find("from")                     ? "pointlight"
                                                                  : "distantlight";
      diag.warning_once("light:" + kind, d.loc, "LightSource",
                        "unknown light shader \"" + kind + "\": using " + fallback);
      kind = fallback;
    }
    if (kind == "ambientlight") {
      lights.push_back(std::make_unique<AmbientLight>(c));
    } else if (kind == "distantlight") {
      const int samples = int(p.get_float("nsamples", float(kDefaultAreaLightSamples)));
      lights.push_back(
          std::make_unique<DistantLight>(c, to_w - from_w, p.get_float("angle", 0), std::clamp(samples, 1, 4096)));
    } else if (kind == "pointlight") {
      lights.push_back(std::make_unique<PointLight>(c, from_w));
    } else {
      float cone = p.get_float("coneangle", kDefaultSpotConeAngle);
      float delta = p.get_float("conedeltaangle", kDefaultSpotConeDeltaAngle);
      float beam = p.get_float("beamdistribution", 2.0f);
      lights.push_back(std::make_unique<SpotLight>(c, from_w, to_w - from_w, cone, delta, beam));
    }
    lights.back()->set_casts_shadows(d.casts_shadows && kind != "ambientlight");
  }
  return lights;
}

}  // namespace darc
