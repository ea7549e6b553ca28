#include "core/scene/ris/ris_bxdf_mapping.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "core/scene/ris/color_texture_params.h"
#include "core/scene/ris/ris_param_reader.h"

namespace darc {

namespace {

// RenderMan's defaults for the parameters darc reads (RenderMan 21-24 documentation).
constexpr Vec3f kPxrSurfaceDiffuseColor{0.18f, 0.18f, 0.18f};
constexpr float kPxrSurfaceSpecularRoughness = 0.2f;
constexpr Vec3f kPxrDisneyBaseColor{0.2f, 0.5f, 0.8f};
constexpr float kPxrDisneySpecular = 0.5f;
constexpr float kPxrDisneyRoughness = 0.25f;
constexpr Vec3f kPxrDiffuseColor{0.5f, 0.5f, 0.5f};
// PxrMarschnerHair's defaults for what maps onto chianghair (the RenderMan 22 plugin defaults,
// ../shared/docs/lookdev.md §1.1): an R cone of 8 degrees, a -3 degree offset, index 1.55.
constexpr float kMarschnerConeAngleR = 8, kMarschnerSpecularOffset = -3, kMarschnerIor = 1.55f;

Param number_param(const std::string& name, float v) {
  Param p;
  p.name = name;
  p.decl.type = ParamType::Float;
  p.floats = {v};
  return p;
}

Param color_param(const std::string& name, Vec3f c) {
  Param p;
  p.name = name;
  p.decl.type = ParamType::Color;
  p.floats = {c.x, c.y, c.z};
  return p;
}

// A Bxdf's colour input: when a PxrTexture feeds it, the surface gets that texture as its colour
// texture (shading/color_texture.h: Cs times the texture, so Cs is 1) and the texture's file,
// manifold and options as parameters; else the input's colour, as before.
Vec3f base_color(RisParamReader& r, const std::string& name, Vec3f fallback, RisSurface& s) {
  const std::optional<RisTexture> t = r.texture(name);
  if (!t) return r.color(name, fallback);
  Param file;
  file.name = kColorTextureParam;
  file.decl.type = ParamType::String;
  file.strings = {t->filename};
  Param manifold;
  manifold.name = kColorTextureManifoldParam;
  manifold.decl.array_size = 6;
  manifold.floats = {t->scale_s, t->scale_t, t->offset_s, t->offset_t, float(t->invert_s), float(t->invert_t)};
  s.params.params.push_back(std::move(file));
  s.params.params.push_back(std::move(manifold));
  s.params.params.push_back(number_param(kColorTextureLinearizeParam, float(t->linearize)));
  s.params.params.push_back(color_param(kColorTextureMissingParam, t->missing_color));
  for (const std::string& d : t->dropped) s.dropped.push_back(name + "'s PxrTexture " + d);
  return {1, 1, 1};
}

float luminance(Vec3f c) { return 0.3f * c.x + 0.6f * c.y + 0.1f * c.z; }  // Disney's tint weights

RisSurface pxr_surface(RisParamReader& r) {
  RisSurface s{"plastic", {}, std::nullopt, {}};
  s.color = base_color(r, "diffuseColor", kPxrSurfaceDiffuseColor, s);
  const float kd = r.number("diffuseGain", 1);
  s.params.params.insert(s.params.params.begin(), {number_param("Ka", kd), number_param("Kd", kd), number_param("Ks", r.number("specularGain", 1)),
                     number_param("roughness", r.number("specularRoughness", kPxrSurfaceSpecularRoughness)),
                     color_param("specularcolor", r.color("specularFaceColor", {0, 0, 0}))});
  return s;
}

RisSurface pxr_disney(RisParamReader& r) {
  RisSurface s{"plastic", {}, std::nullopt, {}};
  const Vec3f base = base_color(r, "baseColor", kPxrDisneyBaseColor, s);
  const float tint = std::clamp(r.number("specularTint", 0), 0.0f, 1.0f);
  const float lum = luminance(base);
  const Vec3f tint_color = lum > 0 ? base / lum : Vec3f{1, 1, 1};
  const Vec3f specular_color = Vec3f{1, 1, 1} * (1 - tint) + tint_color * tint;
  s.color = base;
  s.params.params.insert(s.params.params.begin(), {number_param("Ka", 1), number_param("Kd", 1),
                     number_param("Ks", r.number("specular", kPxrDisneySpecular)),
                     number_param("roughness", r.number("roughness", kPxrDisneyRoughness)),
                     color_param("specularcolor", specular_color)});
  return s;
}

RisSurface pxr_marschner_hair(RisParamReader& r) {
  // Onto the Chiang et al. fibre (lookdev.md §1.6): the R cone's angle is its longitudinal
  // standard deviation (chianghair's "coneangle" finds beta_m for it), the offset is the scales'
  // tilt with the opposite sign (negative toward the root in Marschner's convention, positive in
  // pbrt's), the index as it is. The colour becomes Cs, which chianghair inverts to an absorption.
  // Per-lobe gains and colours are not read (the model's lobes are not separately scaled: that
  // would break its energy balance), so they are reported as parameters darc does not use.
  RisSurface s{"chianghair", {}, std::nullopt, {}};
  // The diffuse colour, else the colour of a PxrHairColor feeding another input (its outputs
  // are one colour here), else Cs as it is.
  s.color = r.optional_color("diffuseColor");
  if (!s.color) s.color = r.any_pattern_color();
  s.params.params = {number_param("coneangle", r.number("specularConeAngleR", kMarschnerConeAngleR)),
                     number_param("alpha", -r.number("specularOffset", kMarschnerSpecularOffset)),
                     number_param("eta", r.number("specularIor", kMarschnerIor))};
  return s;
}

}  // namespace

RisSurfaceMapping map_ris_bxdf(const std::string& name, const ParamList& params, const RisPatterns& patterns) {
  RisParamReader r(params, &patterns);
  RisSurfaceMapping m;
  if (name == "PxrSurface") {
    m.surface = pxr_surface(r);
  } else if (name == "PxrDisney") {
    m.surface = pxr_disney(r);
  } else if (name == "PxrDiffuse") {
    m.surface = {"matte", {}, std::nullopt, {}};
    m.surface.color = base_color(r, "diffuseColor", kPxrDiffuseColor, m.surface);
  } else if (name == "PxrConstant") {
    m.surface = {"constant", {}, r.color("emitColor", {1, 1, 1}), {}};
  } else if (name == "PxrMarschnerHair") {
    m.surface = pxr_marschner_hair(r);
  } else {
    m.surface = {"defaultsurface", {}, std::nullopt, {}};
    m.known = false;
    return m;
  }
  const std::vector<std::string> unread = r.unread();
  m.surface.dropped.insert(m.surface.dropped.begin(), unread.begin(), unread.end());
  m.unevaluated = r.unevaluated();
  return m;
}

void warn_ris_bxdf(const std::string& name, const RisSurfaceMapping& m, Diagnostics& diag, const SourceLoc& loc) {
  if (!m.known) {
    diag.warning_once("ris-bxdf:" + name, loc, "Bxdf", fmt::format("unknown Bxdf \"{}\": using defaultsurface", name));
    return;
  }
  if (!m.surface.dropped.empty()) {
    const std::string list = fmt::format("{}", fmt::join(m.surface.dropped, ", "));
    diag.warning_once("ris-bxdf-dropped:" + name + ":" + list, loc, "Bxdf",
                      fmt::format("{} is mapped to darc's {}: dropped {}", name, m.surface.shader, list));
  }
  for (const std::string& u : m.unevaluated)
    diag.warning_once("ris-bxdf-pattern:" + name + ":" + u, loc, "Bxdf",
                      fmt::format("{}: {} keeps its default colour", name, u));
}

}  // namespace darc
