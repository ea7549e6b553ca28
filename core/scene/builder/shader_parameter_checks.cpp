#include "core/scene/builder/shader_parameter_checks.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string_view>
#include <utility>

namespace darc {

namespace {

// What values a standard parameter takes (docs/parameters.md gives the reasons).
enum class Range {
  Any,             // a finite number: intensity (negative lights are an old RenderMan trick)
  NonNegative,     // Ka, Kd, Ks, Kr, Kt, beamdistribution: a negative weight subtracts light
  Roughness,       // > 0: the specular exponent is 1/roughness
  Eta,             // > 0: an index of refraction
  ConeAngle,       // [0, pi] radians
  ConeDeltaAngle,  // [0, coneangle] radians
  SunAngle,        // [0, 90] degrees: the angular diameter of a distant light
  Triple,          // a colour or a point: 3 finite numbers
};

struct ParameterRule {
  std::string_view name;
  Range range;
};

constexpr ParameterRule kMatte[] = {{"Ka", Range::NonNegative}, {"Kd", Range::NonNegative}};
constexpr ParameterRule kPlastic[] = {{"Ka", Range::NonNegative},
                                      {"Kd", Range::NonNegative},
                                      {"Ks", Range::NonNegative},
                                      {"roughness", Range::Roughness},
                                      {"specularcolor", Range::Triple}};
constexpr ParameterRule kMetal[] = {{"Ka", Range::NonNegative},
                                    {"Ks", Range::NonNegative},
                                    {"Kr", Range::NonNegative},
                                    {"roughness", Range::Roughness}};
constexpr ParameterRule kMirror[] = {{"Ka", Range::NonNegative},       {"Kd", Range::NonNegative},
                                     {"Ks", Range::NonNegative},       {"roughness", Range::Roughness},
                                     {"specularcolor", Range::Triple}, {"Kr", Range::NonNegative}};
constexpr ParameterRule kGlass[] = {{"Ka", Range::NonNegative},       {"Kd", Range::NonNegative},
                                    {"Ks", Range::NonNegative},       {"roughness", Range::Roughness},
                                    {"specularcolor", Range::Triple}, {"Kr", Range::NonNegative},
                                    {"Kt", Range::NonNegative},       {"eta", Range::Eta},
                                    {"transmitcolor", Range::Triple}};
// chianghair's numbers (shading/surface_shader.cpp clamps beta_m, beta_n, eta and alpha to the
// model's ranges, with its own warnings).
constexpr ParameterRule kChiangHair[] = {{"Ka", Range::NonNegative},        {"sigma_a", Range::Triple},
                                         {"color", Range::Triple},          {"reflectance", Range::Triple},
                                         {"eumelanin", Range::NonNegative}, {"pheomelanin", Range::NonNegative},
                                         {"beta_m", Range::Any},            {"beta_n", Range::Any},
                                         {"eta", Range::Any},               {"alpha", Range::Any},
                                         {"coneangle", Range::Any}};
// Also the parameters every AreaLightSource is drawn with, whatever its shader.
constexpr ParameterRule kAmbientLight[] = {{"intensity", Range::Any}, {"lightcolor", Range::Triple}};
constexpr ParameterRule kDistantLight[] = {{"intensity", Range::Any},
                                           {"lightcolor", Range::Triple},
                                           {"from", Range::Triple},
                                           {"to", Range::Triple},
                                           {"angle", Range::SunAngle}};
constexpr ParameterRule kPointLight[] = {
    {"intensity", Range::Any}, {"lightcolor", Range::Triple}, {"from", Range::Triple}};
// coneangle before conedeltaangle: the delta is checked against the (clamped) cone.
constexpr ParameterRule kSpotLight[] = {{"intensity", Range::Any},
                                        {"lightcolor", Range::Triple},
                                        {"from", Range::Triple},
                                        {"to", Range::Triple},
                                        {"coneangle", Range::ConeAngle},
                                        {"conedeltaangle", Range::ConeDeltaAngle},
                                        {"beamdistribution", Range::NonNegative}};

struct ShaderRules {
  std::string_view shader;
  std::span<const ParameterRule> rules;
  bool directed = false;  // shines from "from" toward "to"
};

constexpr ShaderRules kSurfaces[] = {
    {"constant", {}},      {"defaultsurface", {}},       {"matte", kMatte},
    {"plastic", kPlastic}, {"paintedplastic", kPlastic}, {"hair", kPlastic},
    {"metal", kMetal},     {"shinymetal", kMetal},       {"mirror", kMirror},
    {"glass", kGlass},     {"kajiyakay", kPlastic},      {"chianghair", kChiangHair},
};
constexpr ShaderRules kLights[] = {
    {"ambientlight", kAmbientLight},  {"distantlight", kDistantLight, true}, {"shadowdistant", kDistantLight, true},
    {"pointlight", kPointLight},      {"shadowpoint", kPointLight},          {"spotlight", kSpotLight, true},
    {"shadowspot", kSpotLight, true},
};
constexpr ShaderRules kAreaLight = {"", kAmbientLight};

const ShaderRules* rules_for(const std::string& request, const std::string& shader) {
  if (request == "AreaLightSource") return &kAreaLight;
  const std::span<const ShaderRules> table =
      request == "Surface" ? std::span<const ShaderRules>(kSurfaces) : std::span<const ShaderRules>(kLights);
  for (const ShaderRules& r : table)
    if (r.shader == shader) return &r;
  return nullptr;
}

Param* find(ParamList& params, std::string_view name) {
  for (Param& p : params.params)
    if (p.name == name) return &p;
  return nullptr;
}

// Throws unless `p` holds the count of numbers its rule needs.
void check_count(const Param& p, const ParameterRule& rule) {
  const size_t wanted = rule.range == Range::Triple ? 3 : 1;
  if (p.decl.is_string())
    throw RibError(fmt::format("\"{}\" must be {}, found a string", p.name, wanted == 3 ? "3 numbers" : "one number"));
  if (p.floats.size() != wanted)
    throw RibError(fmt::format("\"{}\" must be {}, found {} numbers", p.name, wanted == 3 ? "3 numbers" : "one number",
                               p.floats.size()));
}

// Clamps the one value of a checked parameter, with the warning that says why.
class Clamper {
 public:
  Clamper(const std::string& request, const std::string& shader, Diagnostics& diag, const SourceLoc& loc)
      : request_(request), shader_(shader), diag_(diag), loc_(loc) {}

  void apply(Param& p, const ParameterRule& rule, float cone_angle) {
    float& v = p.floats[0];
    const float given = v;
    switch (rule.range) {
      case Range::NonNegative:
        if (v < 0) warn(p, given, v = 0, "is negative");
        break;
      case Range::Roughness:
        if (v <= 0) warn(p, given, v = kMinRoughness, "is not positive");
        break;
      case Range::Eta:
        if (v <= 0) warn(p, given, v = 1, "is not positive", " (no refraction)");
        break;
      case Range::ConeAngle:
        if (v < 0) warn(p, given, v = 0, "is negative", " (the light sends nothing)");
        if (v > kPi)
          warn(p, given, v = kPi, "is more than pi",
               fmt::format(" (RI angles are radians: {} radians is {:.0f} degrees)", given, given * 180 / kPi));
        break;
      case Range::ConeDeltaAngle:
        if (v < 0) warn(p, given, v = 0, "is negative", " (a hard cone edge)");
        if (v > cone_angle) warn(p, given, v = cone_angle, "is wider than the cone angle");
        break;
      case Range::SunAngle:
        if (v < 0) warn(p, given, v = 0, "is negative", " (hard shadows)");
        if (v > 90) warn(p, given, v = 90, "is more than 90 degrees");
        break;
      case Range::Any:
      case Range::Triple:
        break;
    }
  }

 private:
  static constexpr float kPi = std::numbers::pi_v<float>;

  void warn(const Param& p, float given, float used, std::string_view problem, std::string_view note = {}) {
    diag_.warning(loc_, request_,
                  fmt::format("\"{}\" \"{}\" {} {}: clamped to {}{}", shader_, p.name, given, problem, used, note));
  }

  const std::string& request_;
  const std::string& shader_;
  Diagnostics& diag_;
  const SourceLoc& loc_;
};

}  // namespace

void check_light_positions(const ParamList& params, const Matrix4& shader_to_world) {
  constexpr double kFloatMax = std::numeric_limits<float>::max();
  for (const auto& [name, fallback] : {std::pair{"from", Vec3d{0, 0, 0}}, std::pair{"to", Vec3d{0, 0, 1}}}) {
    const Param* p = params.find(name);
    // As shading/lights.cpp reads them: fewer than 3 numbers mean the default.
    const Vec3d local = p && p->floats.size() >= 3 ? Vec3d{p->floats[0], p->floats[1], p->floats[2]} : fallback;
    const Vec3d world = shader_to_world.transform_point(local);
    if (!(std::abs(world.x) <= kFloatMax && std::abs(world.y) <= kFloatMax && std::abs(world.z) <= kFloatMax))
      throw RibError(fmt::format("\"{}\" ({} {} {}) lies beyond the float range in world space", name, float(local.x),
                                 float(local.y), float(local.z)));
  }
}

ParamList checked_shader_parameters(const std::string& request, const std::string& shader, ParamList params,
                                    Diagnostics& diag, const SourceLoc& loc) {
  const ShaderRules* shader_rules = rules_for(request, shader);
  if (!shader_rules) return params;
  // Every count first: a request with an error is skipped, so it must warn about nothing.
  for (const ParameterRule& rule : shader_rules->rules)
    if (const Param* p = find(params, rule.name)) check_count(*p, rule);
  Clamper clamper(request, shader, diag, loc);
  float cone_angle = kDefaultSpotConeAngle;
  for (const ParameterRule& rule : shader_rules->rules) {
    Param* p = find(params, rule.name);
    if (!p) continue;
    clamper.apply(*p, rule, cone_angle);
    if (rule.range == Range::ConeAngle) cone_angle = p->floats[0];
  }
  if (shader_rules->directed) {
    const Param* from = find(params, "from");
    const Param* to = find(params, "to");
    const std::array<float, 3> f =
        from ? std::array{from->floats[0], from->floats[1], from->floats[2]} : std::array{0.0f, 0.0f, 0.0f};
    const std::array<float, 3> t =
        to ? std::array{to->floats[0], to->floats[1], to->floats[2]} : std::array{0.0f, 0.0f, 1.0f};
    if (f == t)
      diag.warning(loc, request,
                   fmt::format("\"{}\" \"from\" and \"to\" are both ({}, {}, {}): the light has no direction and "
                               "sends no light",
                               shader, f[0], f[1], f[2]));
  }
  return params;
}

}  // namespace darc
