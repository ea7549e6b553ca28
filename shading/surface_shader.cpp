#include "shading/surface_shader.h"

#include "shading/color_texture.h"
#include "shading/shader_params.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/scene/builder/shader_parameter_checks.h"
#include "shading/chiang_hair.h"

namespace darc {

namespace {

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

// The Chiang et al. 2016 fibre (shading/chiang_hair.h), shaded across its width: a strand seen by
// a hider is thinner than what a sample stands for, so its light is the mean over where rays
// enter it (no noise from one entry point per sample, and both hiders see the same strand).
// Under an RI light of colour Cl it sends pi * S * Cl: RI's diffuse() carries no 1/pi (a matte
// surface of Kd 1 facing the light returns Cl), so Cl is an irradiance over pi, and a white fibre
// beside a matte surface has the brightness their albedos give. Absorption from "sigma_a", else
// "color", else melanin, else the strand's Cs as the colour (per vertex Cs gives a root-to-tip
// gradient); ambient light is reflected in that colour. On surfaces (no tangent) it shades like
// plastic with its defaults.
class ChiangHairSurface : public SurfaceShader {
 public:
  ChiangHairSurface(const ChiangHairParams& params, bool absorption_given, float ka)
      : hair_(params), absorption_given_(absorption_given), ka_(ka),
        colour_(ChiangHair::reflectance_from_sigma_a(params.sigma_a, params.beta_n)), surface_fallback_(ParamList{}) {}
  SurfaceLobes lobes(const ShadingPoint& sp) const override {
    if (length_squared(sp.dPdv) == 0.0f) return surface_fallback_.lobes(sp);
    SurfaceLobes l = base_lobes(sp);
    l.ambient = (absorption_given_ ? colour_ : clamp01(sp.Cs)) * ka_;
    l.lit = true;
    return l;
  }
  Vec3f response(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc) const override {
    const Vec3f T = normalize(sp.dPdv);
    if (length_squared(T) == 0.0f) return surface_fallback_.response(sp, l, lc);
    const Vec3f S = hair_.scattering_across(T, -sp.I, lc.L, sigma_a_at(sp));
    return mul(S, lc.Cl) * std::numbers::pi_v<float>;
  }
  // The fibre's lobes drawn across its width (ChiangHair::sample_across): under a dome they are a
  // few degrees wide where the dome's own samples cover the whole sphere.
  bool can_sample_response(const ShadingPoint& sp) const override { return length_squared(sp.dPdv) > 0.0f; }
  // The R lobe's longitudinal standard deviation (TT's is half of it, TRT's twice).
  float response_lobe_width(const ShadingPoint&) const override {
    return std::sqrt(ChiangHair::longitudinal_variance(hair_.params().beta_m));
  }
  bool sample_response(const ShadingPoint& sp, const SurfaceLobes&, const std::array<float, 4>& u,
                       ResponseSample& out) const override {
    const Vec3f T = normalize(sp.dPdv);
    if (length_squared(T) == 0.0f) return false;
    const HairSample s = hair_.sample_across(T, -sp.I, sigma_a_at(sp), u);
    if (!(s.pdf > 0)) return false;
    out = {s.wi, s.S * std::numbers::pi_v<float>, s.pdf};
    return true;
  }
  Vec3f response_and_pdf(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc,
                         float& pdf) const override {
    const Vec3f T = normalize(sp.dPdv);
    if (length_squared(T) == 0.0f) return SurfaceShader::response_and_pdf(sp, l, lc, pdf);
    const ChiangHair::Across a = hair_.evaluate_across(T, -sp.I, lc.L, sigma_a_at(sp));
    pdf = a.pdf;
    return mul(a.S, lc.Cl) * std::numbers::pi_v<float>;
  }

 private:
  static Vec3f clamp01(const Vec3f& c) {
    return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)};
  }
  Vec3f sigma_a_at(const ShadingPoint& sp) const {
    return absorption_given_ ? hair_.params().sigma_a : ChiangHair::sigma_a_from_reflectance(sp.Cs, hair_.params().beta_n);
  }
  ChiangHair hair_;
  bool absorption_given_;
  float ka_;
  Vec3f colour_;
  PlasticSurface surface_fallback_;
};

// Surface "chianghair" with pbrt-v4's hair material parameters (docs/parameters.md): the
// absorption's sources in precedence sigma_a > color > melanin > Cs, each one ignored said once.
std::unique_ptr<SurfaceShader> make_chiang_hair(const ParamList& p, const SourceLoc& loc, Diagnostics& diag) {
  ChiangHairParams c;
  auto in_range = [&](const char* name, float fallback, float lo, float hi) {
    const float v = p.get_float(name, fallback);
    if (v >= lo && v <= hi) return v;
    const float clamped = std::clamp(std::isfinite(v) ? v : fallback, lo, hi);
    diag.warning_once(std::string("chianghair:") + name, loc, "Surface",
                      std::string("chianghair \"") + name + "\" " + std::to_string(v) + " outside [" + std::to_string(lo) +
                          ", " + std::to_string(hi) + "]: using " + std::to_string(clamped));
    return clamped;
  };
  c.beta_m = in_range("beta_m", 0.3f, 0.01f, 1.0f);
  // darc's own: the R lobe's longitudinal standard deviation in degrees (what PxrMarschnerHair's
  // specularConeAngleR gives), when beta_m is not given.
  if (p.find("coneangle")) {
    if (p.find("beta_m"))
      diag.warning_once("chianghair-ignored:coneangle", loc, "Surface",
                        "chianghair: \"coneangle\" ignored: \"beta_m\" given");
    else
      c.beta_m = ChiangHair::beta_m_for_cone_angle(in_range("coneangle", 8.0f, 0.0f, 90.0f));
  }
  c.beta_n = in_range("beta_n", 0.3f, 0.01f, 1.0f);
  c.eta = in_range("eta", 1.55f, 1.0001f, 10.0f);
  c.alpha_degrees = in_range("alpha", 2.0f, -90.0f, 90.0f);
  const char* colour_name = p.find("color") ? "color" : p.find("reflectance") ? "reflectance" : nullptr;
  const bool melanin = p.find("eumelanin") || p.find("pheomelanin");
  auto ignored = [&](const std::string& what, const std::string& why) {
    diag.warning_once("chianghair-ignored:" + what, loc, "Surface", "chianghair: " + what + " ignored: " + why + " given");
  };
  bool given = true;
  if (p.find("sigma_a")) {
    c.sigma_a = param_color(p, "sigma_a", c.sigma_a);
    c.sigma_a = {std::max(c.sigma_a.x, 0.0f), std::max(c.sigma_a.y, 0.0f), std::max(c.sigma_a.z, 0.0f)};
    if (colour_name) ignored(std::string("\"") + colour_name + "\"", "\"sigma_a\"");
    if (melanin) ignored("melanin", "\"sigma_a\"");
  } else if (colour_name) {
    c.sigma_a = ChiangHair::sigma_a_from_reflectance(param_color(p, colour_name, {1, 1, 1}), c.beta_n);
    if (melanin) ignored("melanin", std::string("\"") + colour_name + "\"");
  } else if (melanin) {
    c.sigma_a = ChiangHair::sigma_a_from_melanin(p.get_float("eumelanin", 0), p.get_float("pheomelanin", 0));
  } else {
    given = false;  // the colour is Cs, per point
  }
  return std::make_unique<ChiangHairSurface>(c, given, p.get_float("Ka", 1));
}

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

ShadeResult shade_unshadowed(const SurfaceShader& shader, const ShadingPoint& at, const LightList& lights) {
  ShadingPoint sp = at;
  shader.apply_patterns(sp);
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

namespace {

std::unique_ptr<SurfaceShader> make_untextured_surface_shader(const std::string& name, const ParamList& params,
                                                              const SourceLoc& loc, Diagnostics& diag) {
  if (name == "constant") return std::make_unique<ConstantSurface>();
  if (name == "matte") return std::make_unique<MatteSurface>(params);
  if (name == "plastic" || name == "paintedplastic") return std::make_unique<PlasticSurface>(params);
  if (name == "metal") return std::make_unique<MetalSurface>(params, 0.0f);
  if (name == "shinymetal") return std::make_unique<MetalSurface>(params, 1.0f);
  if (name == "mirror") return std::make_unique<MirrorSurface>(params);
  if (name == "glass") return std::make_unique<GlassSurface>(params);
  if (name == "hair" || name == "kajiyakay") return std::make_unique<HairSurface>(params);
  if (name == "chianghair") return make_chiang_hair(params, loc, diag);
  if (name != "defaultsurface")
    diag.warning_once("surface:" + name, loc, "Surface", "unknown surface shader \"" + name + "\": using defaultsurface");
  return std::make_unique<DefaultSurface>();
}

}  // namespace

std::unique_ptr<SurfaceShader> make_surface_shader(const std::string& name, const ParamList& params,
                                                   const SourceLoc& loc, Diagnostics& diag, Textures* textures) {
  auto shader = make_untextured_surface_shader(name, params, loc, diag);
  return textures ? apply_color_texture(std::move(shader), name, params, *textures, loc, diag) : std::move(shader);
}

std::unique_ptr<SurfaceShader> make_area_light_surface(const ParamList& p) {
  return std::make_unique<EmissiveSurface>(param_color(p, "lightcolor", {1, 1, 1}) * p.get_float("intensity", 1));
}

}  // namespace darc
