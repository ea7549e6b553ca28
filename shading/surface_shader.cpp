#include "shading/surface_shader.h"

#include <algorithm>
#include <cmath>

namespace darc {

namespace {

Vec3f param_color(const ParamList& p, const char* name, Vec3f fallback) {
  const Param* x = p.find(name);
  if (!x || x->floats.size() < 3) return fallback;
  return {x->floats[0], x->floats[1], x->floats[2]};
}

// RI ambient(): the sum of the ambient lights.
Vec3f ambient(const ShadingPoint& sp, const LightList& lights) {
  Vec3f sum;
  LightContribution lc;
  for (const Light* l : lights)
    if (l->illuminate(sp.P, lc) && lc.ambient) sum += lc.Cl;
  return sum;
}

// RI diffuse(N): Lambert over the non-ambient lights in the hemisphere around N.
Vec3f diffuse(const ShadingPoint& sp, const Vec3f& n, const LightList& lights) {
  Vec3f sum;
  LightContribution lc;
  for (const Light* l : lights) {
    if (!l->illuminate(sp.P, lc) || lc.ambient) continue;
    float c = dot(n, lc.L);
    if (c > 0) sum += lc.Cl * c;
  }
  return sum;
}

// RI specular(N, V, roughness): sum of Cl * max(0, N.H)^(1/roughness) (the spec's specularbrdf).
Vec3f specular(const ShadingPoint& sp, const Vec3f& n, const Vec3f& v, float roughness, const LightList& lights) {
  Vec3f sum;
  LightContribution lc;
  float exponent = 1.0f / std::max(roughness, 1e-4f);
  for (const Light* l : lights) {
    if (!l->illuminate(sp.P, lc) || lc.ambient) continue;
    if (dot(n, lc.L) <= 0) continue;
    Vec3f h = normalize(lc.L + v);
    float c = dot(n, h);
    if (c > 0) sum += lc.Cl * std::pow(c, exponent);
  }
  return sum;
}

class ConstantSurface : public SurfaceShader {
 public:
  ShadeResult shade(const ShadingPoint& sp, const LightList&) const override { return {mul(sp.Os, sp.Cs), sp.Os}; }
};

class MatteSurface : public SurfaceShader {
 public:
  explicit MatteSurface(const ParamList& p) : ka_(p.get_float("Ka", 1)), kd_(p.get_float("Kd", 1)) {}
  ShadeResult shade(const ShadingPoint& sp, const LightList& lights) const override {
    Vec3f nf = faceforward(sp.N, sp.I);
    Vec3f c = mul(sp.Cs, ambient(sp, lights) * ka_ + diffuse(sp, nf, lights) * kd_);
    return {mul(sp.Os, c), sp.Os};
  }

 private:
  float ka_, kd_;
};

class PlasticSurface : public SurfaceShader {
 public:
  explicit PlasticSurface(const ParamList& p)
      : ka_(p.get_float("Ka", 1)), kd_(p.get_float("Kd", 0.5f)), ks_(p.get_float("Ks", 0.5f)),
        roughness_(p.get_float("roughness", 0.1f)), specular_color_(param_color(p, "specularcolor", {1, 1, 1})) {}
  ShadeResult shade(const ShadingPoint& sp, const LightList& lights) const override {
    Vec3f nf = faceforward(sp.N, sp.I);
    Vec3f v = -sp.I;
    Vec3f c = mul(sp.Cs, ambient(sp, lights) * ka_ + diffuse(sp, nf, lights) * kd_) +
              mul(specular_color_, specular(sp, nf, v, roughness_, lights) * ks_);
    return {mul(sp.Os, c), sp.Os};
  }

 private:
  float ka_, kd_, ks_, roughness_;
  Vec3f specular_color_;
};

class MetalSurface : public SurfaceShader {
 public:
  explicit MetalSurface(const ParamList& p)
      : ka_(p.get_float("Ka", 1)), ks_(p.get_float("Ks", 1)), roughness_(p.get_float("roughness", 0.1f)) {}
  ShadeResult shade(const ShadingPoint& sp, const LightList& lights) const override {
    Vec3f nf = faceforward(sp.N, sp.I);
    Vec3f c = mul(sp.Cs, ambient(sp, lights) * ka_ + specular(sp, nf, -sp.I, roughness_, lights) * ks_);
    return {mul(sp.Os, c), sp.Os};
  }

 private:
  float ka_, ks_, roughness_;
};

// A hair shader in the manner of PRMan application note 19 (Kajiya & Kay 1989): diffuse from the
// sine between the strand tangent and the light, a specular cone around the tangent. Colour
// comes from Cs (give Cs per vertex for a root-to-tip gradient). On surfaces (no tangent) it
// shades like plastic.
class HairSurface : public SurfaceShader {
 public:
  explicit HairSurface(const ParamList& p)
      : ka_(p.get_float("Ka", 1)), kd_(p.get_float("Kd", 0.6f)), ks_(p.get_float("Ks", 0.35f)),
        roughness_(p.get_float("roughness", 0.15f)), specular_color_(param_color(p, "specularcolor", {1, 1, 1})) {}
  ShadeResult shade(const ShadingPoint& sp, const LightList& lights) const override {
    Vec3f T = normalize(sp.dPdv);
    if (length_squared(T) == 0.0f) {
      PlasticSurface fallback(ParamList{});
      return fallback.shade(sp, lights);
    }
    Vec3f V = -sp.I;
    float cos_tv = dot(T, V), sin_tv = std::sqrt(std::max(0.0f, 1 - cos_tv * cos_tv));
    float exponent = 1.0f / std::max(roughness_, 1e-4f);
    Vec3f diff, spec;
    LightContribution lc;
    for (const Light* l : lights) {
      if (!l->illuminate(sp.P, lc) || lc.ambient) continue;
      float cos_tl = dot(T, lc.L), sin_tl = std::sqrt(std::max(0.0f, 1 - cos_tl * cos_tl));
      diff += lc.Cl * sin_tl;
      float cone = cos_tl * cos_tv + sin_tl * sin_tv;
      if (cone > 0) spec += lc.Cl * std::pow(cone, exponent);
    }
    Vec3f c = mul(sp.Cs, ambient(sp, lights) * ka_ + diff * kd_) + mul(specular_color_, spec * ks_);
    return {mul(sp.Os, c), sp.Os};
  }

 private:
  float ka_, kd_, ks_, roughness_;
  Vec3f specular_color_;
};

// PRMan/Aqsis defaultsurface: a headlight look that shows geometry without any light:
// Ci = Os * Cs * (Ka + Kd * (N.I)^2) with Ka = 0.2, Kd = 0.8.
class DefaultSurface : public SurfaceShader {
 public:
  ShadeResult shade(const ShadingPoint& sp, const LightList&) const override {
    float d = dot(normalize(sp.N), sp.I);
    Vec3f c = sp.Cs * (0.2f + 0.8f * d * d);
    return {mul(sp.Os, c), sp.Os};
  }
};

class EmissiveSurface : public SurfaceShader {
 public:
  explicit EmissiveSurface(Vec3f e) : e_(e) {}
  ShadeResult shade(const ShadingPoint& sp, const LightList&) const override { return {mul(sp.Os, e_), sp.Os}; }

 private:
  Vec3f e_;
};

}  // namespace

std::unique_ptr<SurfaceShader> make_surface_shader(const std::string& name, const ParamList& params,
                                                   const SourceLoc& loc, Diagnostics& diag) {
  if (name == "constant") return std::make_unique<ConstantSurface>();
  if (name == "matte") return std::make_unique<MatteSurface>(params);
  if (name == "plastic" || name == "paintedplastic") return std::make_unique<PlasticSurface>(params);
  if (name == "metal" || name == "shinymetal") return std::make_unique<MetalSurface>(params);
  if (name == "hair") return std::make_unique<HairSurface>(params);
  if (name != "defaultsurface")
    diag.warning_once("surface:" + name, loc, "Surface", "unknown surface shader \"" + name + "\": using defaultsurface");
  return std::make_unique<DefaultSurface>();
}

std::unique_ptr<SurfaceShader> make_area_light_surface(const ParamList& p) {
  return std::make_unique<EmissiveSurface>(param_color(p, "lightcolor", {1, 1, 1}) * p.get_float("intensity", 1));
}

}  // namespace darc
