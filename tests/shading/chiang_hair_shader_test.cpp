// Surface "chianghair": the fibre model as an RI shader (parameters, their precedence, the
// colour from Cs, and its light: pi * S * Cl for an RI light).
#include "shading/chiang_hair.h"
#include "shading/lights.h"
#include "shading/surface_shader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace darc {
namespace {

Param number(const char* name, std::vector<float> v) {
  Param x;
  x.name = name;
  x.decl.type = v.size() == 3 ? ParamType::Color : ParamType::Float;
  x.floats = std::move(v);
  return x;
}

ParamList params(std::vector<Param> list) {
  ParamList p;
  p.params = std::move(list);
  return p;
}

struct Fixture {
  std::vector<Diagnostic> seen;
  Diagnostics diag{[this](const Diagnostic& d) { seen.push_back(d); }};
};

// A strand along +z seen from +x, lit by a distant light of intensity 1 from `from`.
ShadingPoint strand() {
  ShadingPoint sp;
  sp.N = {1, 0, 0};
  sp.I = {-1, 0, 0};
  sp.Cs = {0.8f, 0.5f, 0.3f};
  sp.Os = {1, 1, 1};
  sp.dPdv = {0, 0, 1};
  return sp;
}

Vec3f lit(const SurfaceShader& shader, const ShadingPoint& sp, const Vec3f& from, Diagnostics& diag) {
  LightDesc d{"distantlight", params({number("from", {from.x, from.y, from.z}), number("to", {0, 0, 0})}), Matrix4{}, {}};
  auto lights = make_lights({d}, diag);
  return shade_unshadowed(shader, sp, {lights[0].get()}).Ci;
}

TEST(ChiangHairShader, SendsPiTimesTheFibresScatteringOfAnRiLight) {
  Fixture f;
  const ParamList p = params({number("sigma_a", {0.2f, 0.4f, 0.8f}), number("beta_m", {0.25f}), number("beta_n", {0.4f})});
  auto shader = make_surface_shader("chianghair", p, {}, f.diag);
  ChiangHairParams c;
  c.sigma_a = {0.2f, 0.4f, 0.8f};
  c.beta_m = 0.25f;
  c.beta_n = 0.4f;
  const ChiangHair hair(c);
  const ShadingPoint sp = strand();
  for (const Vec3f from : {Vec3f{1, 0.2f, 0.3f}, Vec3f{-1, 0.1f, -0.2f}, Vec3f{0.2f, 1, 0.5f}}) {
    const Vec3f expected = hair.scattering_across(sp.dPdv, -sp.I, normalize(from)) * std::numbers::pi_v<float>;
    const Vec3f got = lit(*shader, sp, from, f.diag);
    EXPECT_NEAR(got.x, expected.x, 1e-5f);
    EXPECT_NEAR(got.z, expected.z, 1e-5f);
  }
  EXPECT_TRUE(f.seen.empty());
}

TEST(ChiangHairShader, ForwardScatteringOutshinesBackscattering) {
  // A translucent fibre sends most light on through (TT): lit from behind it is brighter than lit
  // from the viewer's side, unlike a Lambertian surface.
  Fixture f;
  auto shader = make_surface_shader("chianghair", params({number("color", {0.8f, 0.8f, 0.8f})}), {}, f.diag);
  const ShadingPoint sp = strand();
  EXPECT_GT(lit(*shader, sp, {-1, 0.05f, 0}, f.diag).x, 5 * lit(*shader, sp, {1, 0.05f, 0}, f.diag).x);
}

TEST(ChiangHairShader, WithoutAnAbsorptionTheColourIsCs) {
  Fixture f;
  auto from_cs = make_surface_shader("chianghair", {}, {}, f.diag);
  auto from_colour = make_surface_shader("chianghair", params({number("color", {0.8f, 0.5f, 0.3f})}), {}, f.diag);
  const ShadingPoint sp = strand();
  const Vec3f a = lit(*from_cs, sp, {-1, 0.3f, 0.2f}, f.diag), b = lit(*from_colour, sp, {-1, 0.3f, 0.2f}, f.diag);
  EXPECT_NEAR(a.x, b.x, 1e-6f);
  EXPECT_NEAR(a.z, b.z, 1e-6f);
  EXPECT_LT(a.z, a.x) << "a warm Cs absorbs blue most";
  ShadingPoint darker = sp;
  darker.Cs = {0.2f, 0.1f, 0.05f};
  EXPECT_LT(lit(*from_cs, darker, {-1, 0.3f, 0.2f}, f.diag).x, a.x);
}

TEST(ChiangHairShader, AbsorptionSourcesFollowPbrtsPrecedenceAndSaySoOnce) {
  Fixture f;
  auto shader = make_surface_shader(
      "chianghair", params({number("sigma_a", {0.1f, 0.1f, 0.1f}), number("color", {0.5f, 0.5f, 0.5f}), number("eumelanin", {2})}),
      {}, f.diag);
  ASSERT_EQ(f.seen.size(), 2u);
  EXPECT_NE(f.seen[0].message.find("\"color\" ignored: \"sigma_a\" given"), std::string::npos) << f.seen[0].message;
  EXPECT_NE(f.seen[1].message.find("melanin ignored"), std::string::npos) << f.seen[1].message;
  // sigma_a won: a grey absorption gives a grey response.
  const Vec3f c = lit(*shader, strand(), {-1, 0.3f, 0.2f}, f.diag);
  EXPECT_NEAR(c.x, c.z, 1e-6f);
}

TEST(ChiangHairShader, RoughnessOutsideTheModelsRangeIsClampedWithAWarning) {
  Fixture f;
  auto clamped = make_surface_shader("chianghair", params({number("beta_m", {2.5f})}), {}, f.diag);
  auto one = make_surface_shader("chianghair", params({number("beta_m", {1})}), {}, f.diag);
  ASSERT_EQ(f.seen.size(), 1u);
  EXPECT_NE(f.seen[0].message.find("beta_m"), std::string::npos);
  EXPECT_EQ(lit(*clamped, strand(), {-1, 0.3f, 0.2f}, f.diag).x, lit(*one, strand(), {-1, 0.3f, 0.2f}, f.diag).x);
}

TEST(ChiangHairShader, ConeAngleSetsTheLongitudinalRoughness) {
  Fixture f;
  auto cone = make_surface_shader("chianghair", params({number("coneangle", {8})}), {}, f.diag);
  auto beta = make_surface_shader("chianghair", params({number("beta_m", {ChiangHair::beta_m_for_cone_angle(8)})}), {},
                                  f.diag);
  const Vec3f a = lit(*cone, strand(), {-1, 0.3f, 0.2f}, f.diag), b = lit(*beta, strand(), {-1, 0.3f, 0.2f}, f.diag);
  EXPECT_NEAR(a.x, b.x, 1e-6f * std::max(1.0f, b.x));
  EXPECT_TRUE(f.seen.empty());
}

TEST(ChiangHairShader, KajiyaKayStaysUnderItsOwnName) {
  Fixture f;
  auto old_name = make_surface_shader("hair", {}, {}, f.diag), new_name = make_surface_shader("kajiyakay", {}, {}, f.diag);
  EXPECT_EQ(lit(*old_name, strand(), {1, 0.5f, 0.2f}, f.diag), lit(*new_name, strand(), {1, 0.5f, 0.2f}, f.diag));
  EXPECT_TRUE(f.seen.empty());
}

}  // namespace
}  // namespace darc
