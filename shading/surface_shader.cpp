#include "shading/surface_shader.h"

#include <algorithm>
#include <cmath>

#include "core/scene/builder/shader_parameter_checks.h"

namespace darc {

namespace {

Vec3f param_color(const ParamList& p, const char* name, Vec3f fallback) {
  const Param* x = p.find(name);
  if (!x || x->floats.size() < 3) return fallback;
  return {x->floats[0], x->floats[1], x->floats[2]};
}

// RI diffuse() for one light: Lambert in the hemisphere around n.
Vec3f diffuse_term(const Vec3f& n, const LightContribution& lc) {
  float c = dot(n, lc.L);
  return c > 0 ? lc.Cl * c : Vec3f{};
}

// RI specular() for one light: Cl * max(0, N.H)^(1/roughness) (the spec's specularbrdf), for
// lights in the hemisphere around n.
Vec3f specular_term(const Vec3f& n, const Vec3f& v, float roughness, const LightContribution& lc) {
  if (dot(n, lc.L) <= 0) return {};
  Vec3f h = normalize(lc.L + v);
  float c = dot(n, h);
  return c > 0 ? lc.Cl * std::pow(c, 1.0f / std::max(roughness, kMinRoughness)) : Vec3f{};
}

SurfaceLobes base_lobes(const ShadingPoint& sp) {
  SurfaceLobes l;
  l.Oi = sp.Os;
  l.Nf = faceforward(sp.N, sp.I);
  return l;
}

class ConstantSurface : public SurfaceShader {
 public:
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = base_lobes(sp);
    l.emission = sp.Cs;
    return l;
  }
};

class MatteSurface : public SurfaceShader {
 public:
  explicit MatteSurface(const ParamList& p) : ka_(p.get_float("Ka", 1)), kd_(p.get_float("Kd", 1)) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = base_lobes(sp);
    l.ambient = sp.Cs * ka_;
    l.lit = kd_ != 0;
    return l;
  }
  Vec3f response(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc) const override {
    return mul(sp.Cs, diffuse_term(l.Nf, lc) * kd_);
  }

 private:
  float ka_, kd_;
};

// plastic, and the diffuse + specular part of mirror and glass:
// Cs * (Ka ambient + Kd diffuse) + specularcolor * Ks * specular.
class PlasticSurface : public SurfaceShader {
 public:
  PlasticSurface(const ParamList& p, float ka, float kd, float ks, float roughness)
      : ka_(p.get_float("Ka", ka)), kd_(p.get_float("Kd", kd)), ks_(p.get_float("Ks", ks)),
        roughness_(p.get_float("roughness", roughness)), specular_color_(param_color(p, "specularcolor", {1, 1, 1})) {}
  explicit PlasticSurface(const ParamList& p) : PlasticSurface(p, 1, 0.5f, 0.5f, 0.1f) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = base_lobes(sp);
    l.ambient = sp.Cs * ka_;
    l.lit = kd_ != 0 || ks_ != 0;
    return l;
  }
  Vec3f response(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc) const override {
    return mul(sp.Cs, diffuse_term(l.Nf, lc) * kd_) + mul(specular_color_, specular_term(l.Nf, -sp.I, roughness_, lc) * ks_);
  }

 protected:
  float ka_, kd_, ks_, roughness_;
  Vec3f specular_color_;
};

// metal and shinymetal: Cs * (Ka ambient + Ks specular + Kr reflection). RI's metal has no Kr
// (default 0 here); shinymetal's Kr (default 1) reads an environment map in RSL, a traced ray here.
class MetalSurface : public SurfaceShader {
 public:
  MetalSurface(const ParamList& p, float kr)
      : ka_(p.get_float("Ka", 1)), ks_(p.get_float("Ks", 1)), kr_(p.get_float("Kr", kr)),
        roughness_(p.get_float("roughness", 0.1f)) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = base_lobes(sp);
    l.ambient = sp.Cs * ka_;
    l.reflection = sp.Cs * kr_;
    l.lit = ks_ != 0;
    return l;
  }
  Vec3f response(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc) const override {
    return mul(sp.Cs, specular_term(l.Nf, -sp.I, roughness_, lc) * ks_);
  }

 private:
  float ka_, ks_, kr_, roughness_;
};

// BMRT's mirror: plastic's terms (Ka 0, Kd 0, Ks 1, roughness 0.05) plus Kr (1) times the
// mirror reflection.
class MirrorSurface : public PlasticSurface {
 public:
  explicit MirrorSurface(const ParamList& p) : PlasticSurface(p, 0, 0, 1, 0.05f), kr_(p.get_float("Kr", 1)) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = PlasticSurface::lobes(sp);
    l.reflection = Vec3f{1, 1, 1} * kr_;
    return l;
  }

 private:
  float kr_;
};

// BMRT's glass (Gritz, Advanced RenderMan ch. 9 MaterialGlass): plastic's terms (Ka 0.2, Kd 0,
// Ks 0.5, roughness 0.05) plus Kr * F along the reflection and Kt * (1 - F) * transmitcolor along
// the refraction, F the dielectric Fresnel term for eta (1.5: the glass's index; a ray entering
// through the side N points to sees 1/eta, one leaving sees eta). Total internal reflection:
// F = 1, no refracted ray.
class GlassSurface : public PlasticSurface {
 public:
  explicit GlassSurface(const ParamList& p)
      : PlasticSurface(p, 0.2f, 0, 0.5f, 0.05f), kr_(p.get_float("Kr", 1)), kt_(p.get_float("Kt", 1)),
        eta_(p.get_float("eta", 1.5f)), transmit_color_(param_color(p, "transmitcolor", {1, 1, 1})) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = PlasticSurface::lobes(sp);
    const bool entering = dot(sp.I, sp.N) < 0;
    l.eta = eta_ > 0 ? (entering ? 1.0f / eta_ : eta_) : 1.0f;
    const float f = dielectric_fresnel(-dot(sp.I, l.Nf), l.eta);
    l.reflection = Vec3f{1, 1, 1} * (kr_ * f);
    l.transmission = transmit_color_ * (kt_ * (1 - f));
    return l;
  }

 private:
  float kr_, kt_, eta_;
  Vec3f transmit_color_;
};

// A hair shader in the manner of PRMan application note 19 (Kajiya & Kay 1989): diffuse from the
// sine between the strand tangent and the light, a specular cone around the tangent. Colour
// comes from Cs (give Cs per vertex for a root-to-tip gradient). On surfaces (no tangent) it
// shades like plastic with its defaults.
class HairSurface : public SurfaceShader {
 public:
  explicit HairSurface(const ParamList& p)
      : ka_(p.get_float("Ka", 1)), kd_(p.get_float("Kd", 0.6f)), ks_(p.get_float("Ks", 0.35f)),
        roughness_(p.get_float("roughness", 0.15f)), specular_color_(param_color(p, "specularcolor", {1, 1, 1})),
        surface_fallback_(ParamList{}) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    if (length_squared(sp.dPdv) == 0.0f) return surface_fallback_.lobes(sp);
    SurfaceLobes l = base_lobes(sp);
    l.ambient = sp.Cs * ka_;
    l.lit = kd_ != 0 || ks_ != 0;
    return l;
  }
  Vec3f response(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc) const override {
    Vec3f T = normalize(sp.dPdv);
    if (length_squared(T) == 0.0f) return surface_fallback_.response(sp, l, lc);
    Vec3f V = -sp.I;
    float cos_tv = dot(T, V), sin_tv = std::sqrt(std::max(0.0f, 1 - cos_tv * cos_tv));
    float cos_tl = dot(T, lc.L), sin_tl = std::sqrt(std::max(0.0f, 1 - cos_tl * cos_tl));
    Vec3f c = mul(sp.Cs, lc.Cl * (sin_tl * kd_));
    float cone = cos_tl * cos_tv + sin_tl * sin_tv;
    if (cone > 0) c += mul(specular_color_, lc.Cl * (std::pow(cone, 1.0f / std::max(roughness_, kMinRoughness)) * ks_));
    return c;
  }

 private:
  float ka_, kd_, ks_, roughness_;
  Vec3f specular_color_;
  PlasticSurface surface_fallback_;
};

// PRMan/Aqsis defaultsurface: a headlight look that shows geometry without any light:
// Ci = Os * Cs * (Ka + Kd * (N.I)^2) with Ka = 0.2, Kd = 0.8.
class DefaultSurface : public SurfaceShader {
 public:
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = base_lobes(sp);
    float d = dot(normalize(sp.N), sp.I);
    l.emission = sp.Cs * (0.2f + 0.8f * d * d);
    return l;
  }
};

class EmissiveSurface : public SurfaceShader {
 public:
  explicit EmissiveSurface(Vec3f e) : e_(e) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    SurfaceLobes l = base_lobes(sp);
    l.emission = e_;
    return l;
  }

 private:
  Vec3f e_;
};

}  // namespace

float dielectric_fresnel(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  float sin_t2 = eta * eta * (1 - cos_i * cos_i);
  if (sin_t2 >= 1) return 1;
  float cos_t = std::sqrt(1 - sin_t2);
  // eta = n_from / n_to: with n_from = eta, n_to = 1 (only the ratio matters).
  float r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  float r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (r_s * r_s + r_p * r_p);
}

ShadeResult shade_unshadowed(const SurfaceShader& shader, const ShadingPoint& sp, const LightList& lights) {
  SurfaceLobes l = shader.lobes(sp);
  Vec3f c = l.emission;
  LightContribution lc;
  for (const Light* light : lights) {
    if (!light->illuminate(sp.P, lc)) continue;
    if (lc.ambient)
      c += mul(l.ambient, lc.Cl);
    else if (l.lit)
      c += shader.response(sp, l, lc);
  }
  return {mul(l.Oi, c), l.Oi};
}

std::unique_ptr<SurfaceShader> make_surface_shader(const std::string& name, const ParamList& params,
                                                   const SourceLoc& loc, Diagnostics& diag) {
  if (name == "constant") return std::make_unique<ConstantSurface>();
  if (name == "matte") return std::make_unique<MatteSurface>(params);
  if (name == "plastic" || name == "paintedplastic") return std::make_unique<PlasticSurface>(params);
  if (name == "metal") return std::make_unique<MetalSurface>(params, 0.0f);
  if (name == "shinymetal") return std::make_unique<MetalSurface>(params, 1.0f);
  if (name == "mirror") return std::make_unique<MirrorSurface>(params);
  if (name == "glass") return std::make_unique<GlassSurface>(params);
  if (name == "hair") return std::make_unique<HairSurface>(params);
  if (name != "defaultsurface")
    diag.warning_once("surface:" + name, loc, "Surface", "unknown surface shader \"" + name + "\": using defaultsurface");
  return std::make_unique<DefaultSurface>();
}

std::unique_ptr<SurfaceShader> make_area_light_surface(const ParamList& p) {
  return std::make_unique<EmissiveSurface>(param_color(p, "lightcolor", {1, 1, 1}) * p.get_float("intensity", 1));
}

}  // namespace darc
