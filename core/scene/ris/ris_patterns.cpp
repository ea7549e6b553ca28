#include "core/scene/ris/ris_patterns.h"

#include <algorithm>
#include <cmath>

namespace darc {

namespace {

// melanin -> pigment amount: -ln(1 - melanin), capped where 1 - melanin reaches this (black).
constexpr float kMinMelaninRemainder = 1e-4f;
// Absorption per unit eumelanin and pheomelanin (d'Eon et al. 2011 §6.1, as Blender writes them).
constexpr Vec3f kEumelaninAbsorption{0.506f, 0.841f, 1.653f};
constexpr Vec3f kPheomelaninAbsorption{0.343f, 0.733f, 1.924f};
// Chiang et al. 2016's polynomial in the radial roughness, at its usual 0.3:
// 5.969 - 0.215 b + 2.532 b^2 - 10.73 b^3 + 5.574 b^4 + 0.245 b^5.
constexpr float kChiangRoughness = 0.3f;

float chiang_denominator(float b) {
  return 5.969f - 0.215f * b + 2.532f * b * b - 10.73f * b * b * b + 5.574f * b * b * b * b +
         0.245f * b * b * b * b * b;
}

}  // namespace

std::string pattern_handle(const std::string& reference) { return reference.substr(0, reference.find(':')); }

Vec3f melanin_hair_color(float melanin, float redness) {
  melanin = std::clamp(melanin, 0.0f, 1.0f);
  redness = std::clamp(redness, 0.0f, 1.0f);
  const float amount = -std::log(std::max(1 - melanin, kMinMelaninRemainder));
  const Vec3f sigma = kEumelaninAbsorption * (amount * (1 - redness)) + kPheomelaninAbsorption * (amount * redness);
  // Chiang: sigma = (ln(colour) / d)^2, so colour = exp(-sqrt(sigma) * d).
  const float d = chiang_denominator(kChiangRoughness);
  return {std::exp(-std::sqrt(sigma.x) * d), std::exp(-std::sqrt(sigma.y) * d), std::exp(-std::sqrt(sigma.z) * d)};
}

std::optional<Vec3f> constant_pattern_color(const RisPattern& pattern) {
  const ParamList& p = pattern.params;
  if (pattern.name == "PxrHairColor") {
    // Physical mode only; PxrHairColor's defaults were not found in Pixar's documentation: darc
    // takes medium brown hair when a value is absent (docs in README).
    constexpr float kDefaultMelanin = 0.3f, kDefaultRedness = 0.5f;
    const Param* m = p.find("melanin");
    const Param* r = p.find("melaninRedness");
    const float melanin = m && !m->decl.is_string() && !m->floats.empty() ? m->floats[0] : kDefaultMelanin;
    const float redness = r && !r->decl.is_string() && !r->floats.empty() ? r->floats[0] : kDefaultRedness;
    return melanin_hair_color(melanin, redness);
  }
  if (p.params.size() == 1) {
    const Param& only = p.params[0];
    if (only.decl.type == ParamType::Color && !only.decl.is_string() && only.floats.size() == 3)
      return Vec3f{only.floats[0], only.floats[1], only.floats[2]};
  }
  return std::nullopt;
}

namespace {

float number_of(const Param* p, float fallback) {
  return p && !p->decl.is_string() && !p->decl.reference && !p->floats.empty() ? p->floats[0] : fallback;
}

}  // namespace

std::optional<RisTexture> texture_pattern(const RisPattern& pattern, const RisPatterns& patterns) {
  if (pattern.name != "PxrTexture") return std::nullopt;
  const ParamList& p = pattern.params;
  const Param* file = p.find("filename");
  if (!file || !file->decl.is_string() || file->strings.empty() || file->strings[0].empty()) return std::nullopt;
  RisTexture t;
  t.filename = file->strings[0];
  bool invert_t = number_of(p.find("invertT"), 1) != 0;
  t.linearize = number_of(p.find("linearize"), 0) != 0;
  if (const Param* missing = p.find("missingColor");
      missing && !missing->decl.is_string() && !missing->decl.reference && missing->floats.size() >= 3)
    t.missing_color = {missing->floats[0], missing->floats[1], missing->floats[2]};
  for (const Param& q : p.params)
    if (q.name != "filename" && q.name != "invertT" && q.name != "linearize" && q.name != "missingColor" &&
        q.name != "manifold")
      t.dropped.push_back(q.name);
  const Param* manifold = p.find("manifold");
  if (manifold && manifold->decl.reference && !manifold->strings.empty()) {
    const auto it = patterns.find(pattern_handle(manifold->strings[0]));
    if (it != patterns.end() && it->second.name == "PxrManifold2D") {
      const ParamList& m = it->second.params;
      t.scale_s = number_of(m.find("scaleS"), 1);
      t.scale_t = number_of(m.find("scaleT"), 1);
      t.offset_s = number_of(m.find("offsetS"), 0);
      t.offset_t = number_of(m.find("offsetT"), 0);
      t.invert_s = number_of(m.find("invertS"), 0) != 0;
      invert_t = invert_t || number_of(m.find("invertT"), 1) != 0;
      for (const Param& q : m.params)
        if (q.name != "scaleS" && q.name != "scaleT" && q.name != "offsetS" && q.name != "offsetT" &&
            q.name != "invertS" && q.name != "invertT" && !(q.name == "angle" && number_of(&q, 0) == 0))
          t.dropped.push_back("PxrManifold2D " + q.name);
    } else {
      t.dropped.push_back(it == patterns.end() ? "manifold (no such Pattern)" : "manifold " + it->second.name);
    }
  }
  t.invert_t = invert_t;
  return t;
}

}  // namespace darc
