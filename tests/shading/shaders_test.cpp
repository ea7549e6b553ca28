// The RI standard shaders and lights against their Appendix A formulas.
#include "shading/lights.h"
#include "shading/surface_shader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace darc {
namespace {

ParamList params(std::initializer_list<std::pair<const char*, std::vector<float>>> values) {
  ParamList p;
  for (auto& [name, v] : values) {
    Param x;
    x.name = name;
    x.decl.type = v.size() == 3 ? ParamType::Color : ParamType::Float;
    x.floats = v;
    p.params.push_back(x);
  }
  return p;
}

LightDesc light(const std::string& shader, ParamList p) { return LightDesc{shader, std::move(p), Matrix4{}, {}}; }

struct Fixture {
  Diagnostics diag{[](const Diagnostic&) {}};
  std::vector<std::unique_ptr<Light>> lights;
  LightList list() const {
    LightList l;
    for (auto& x : lights) l.push_back(x.get());
    return l;
  }
};

ShadingPoint facing_up() {
  // A surface at the origin with normal +y, seen from above.
  ShadingPoint sp;
  sp.N = {0, 1, 0};
  sp.I = {0, -1, 0};
  sp.Cs = {0.5f, 0.25f, 1.0f};
  sp.Os = {1, 1, 1};
  return sp;
}

TEST(Shaders, MatteIsLambertPlusAmbient) {
  Fixture f;
  // Distant light from 60 degrees off the normal: cos = 0.5.
  float s = std::sin(std::numbers::pi_v<float> / 3), c = std::cos(std::numbers::pi_v<float> / 3);
  f.lights = make_lights({light("distantlight", params({{"intensity", {2}}, {"from", {s, c, 0}}, {"to", {0, 0, 0}}})),
                          light("ambientlight", params({{"intensity", {0.1f}}}))},
                         f.diag);
  auto matte = make_surface_shader("matte", params({{"Kd", {0.8f}}}), {}, f.diag);
  ShadeResult r = shade_unshadowed(*matte, facing_up(), f.list());
  // Ci = Cs * (Ka * 0.1 + Kd * 2 * 0.5)
  float k = 1.0f * 0.1f + 0.8f * 2.0f * 0.5f;
  EXPECT_NEAR(r.Ci.x, 0.5f * k, 1e-5f);
  EXPECT_NEAR(r.Ci.z, 1.0f * k, 1e-5f);
  EXPECT_EQ(r.Oi, (Vec3f{1, 1, 1}));
}

TEST(Shaders, MatteFaceForwardsTheNormal) {
  Fixture f;
  f.lights = make_lights({light("distantlight", params({{"from", {0, 1, 0}}, {"to", {0, 0, 0}}}))}, f.diag);
  auto matte = make_surface_shader("matte", {}, {}, f.diag);
  ShadingPoint sp = facing_up();
  sp.N = {0, -1, 0};  // the geometric normal points away from the viewer
  EXPECT_NEAR(shade_unshadowed(*matte, sp, f.list()).Ci.x, 0.5f, 1e-6f);
}

TEST(Shaders, PointLightFallsOffWithTheSquareOfTheDistance) {
  Fixture f;
  f.lights = make_lights({light("pointlight", params({{"intensity", {8}}, {"from", {0, 2, 0}}}))}, f.diag);
  LightContribution lc;
  ASSERT_TRUE(f.lights[0]->illuminate({0, 0, 0}, lc));
  EXPECT_NEAR(lc.Cl.x, 2.0f, 1e-6f);
  EXPECT_NEAR(lc.L.y, 1.0f, 1e-6f);
}

TEST(Shaders, SpotlightConeAndFalloff) {
  Fixture f;
  f.lights = make_lights({light("spotlight", params({{"from", {0, 1, 0}}, {"to", {0, 0, 0}}}))}, f.diag);
  LightContribution lc;
  ASSERT_TRUE(f.lights[0]->illuminate({0, 0, 0}, lc));
  EXPECT_NEAR(lc.Cl.x, 1.0f, 1e-6f) << "on the axis: cos^2 = 1, distance 1, inside the cone";
  EXPECT_FALSE(f.lights[0]->illuminate({1, 0, 0}, lc)) << "45 degrees is outside the 30 degree cone";
}

TEST(Shaders, SpotlightConeEdgeIsFilteredOverTheFootprint) {
  // A cone of 30 degrees with no soft edge (conedeltaangle 0), from 1 above the plane y = 0: its
  // edge crosses the plane at x = tan 30. An exact point there is lit or not; a footprint 0.2
  // wide around it gets the box-filtered step, about half, and a footprint well inside or
  // outside gets the exact value.
  Fixture f;
  f.lights = make_lights({light("spotlight", params({{"from", {0, 1, 0}},
                                                      {"to", {0, 0, 0}},
                                                      {"coneangle", {float(M_PI / 6)}},
                                                      {"conedeltaangle", {0}}}))},
                         f.diag);
  const float edge = std::tan(float(M_PI / 6));
  auto lit = [&](float x, float radius) {
    LightContribution lc;
    if (!f.lights[0]->illuminate({x, 0, 0}, lc, radius)) return 0.0f;
    return lc.Cl.x;
  };
  const float inside = lit(edge - 0.2f, 0.1f);
  EXPECT_EQ(lit(edge + 1e-3f, 0), 0.0f);
  EXPECT_GT(lit(edge - 1e-3f, 0), 0.5f);
  const float filtered = lit(edge, 0.1f);
  EXPECT_GT(filtered, 0.3f * inside);
  EXPECT_LT(filtered, 0.7f * inside);
  EXPECT_EQ(lit(edge - 0.2f, 0.1f), lit(edge - 0.2f, 0)) << "far from the edge the footprint changes nothing";
  EXPECT_EQ(lit(edge + 0.2f, 0.1f), 0.0f);
}

TEST(Shaders, PlasticHighlightPeaksAtTheMirrorDirection) {
  Fixture f;
  f.lights = make_lights({light("distantlight", params({{"from", {0, 1, 0}}, {"to", {0, 0, 0}}}))}, f.diag);
  auto plastic = make_surface_shader("plastic", params({{"Ka", {0}}, {"Kd", {0}}}), {}, f.diag);
  ShadeResult r = shade_unshadowed(*plastic, facing_up(), f.list());
  EXPECT_NEAR(r.Ci.x, 0.5f, 1e-5f) << "Ks * specularcolor * (N.H)^(1/roughness) with N.H = 1";
  ShadingPoint off = facing_up();
  off.I = normalize(Vec3f{1, -1, 0});
  // Viewed 45 degrees off the normal, H is 22.5 degrees off it.
  float expected = 0.5f * std::pow(std::cos(std::numbers::pi_v<float> / 8), 1.0f / 0.1f);
  EXPECT_NEAR(shade_unshadowed(*plastic, off, f.list()).Ci.x, expected, 1e-4f);
}

TEST(Shaders, HairIsKajiyaKayAroundTheTangent) {
  Fixture f;
  f.lights = make_lights({light("distantlight", params({{"from", {0, 1, 0}}, {"to", {0, 0, 0}}}))}, f.diag);
  auto hair = make_surface_shader("hair", params({{"Ka", {0}}, {"Ks", {0}}}), {}, f.diag);
  ShadingPoint sp = facing_up();
  sp.dPdv = {1, 0, 0};  // light perpendicular to the strand: sin = 1
  EXPECT_NEAR(shade_unshadowed(*hair, sp, f.list()).Ci.x, 0.5f * 0.6f, 1e-5f);
  sp.dPdv = normalize(Vec3f{1, 1, 0});  // 45 degrees: sin = 0.707
  EXPECT_NEAR(shade_unshadowed(*hair, sp, f.list()).Ci.x, 0.5f * 0.6f * std::sqrt(0.5f), 1e-5f);
}

TEST(Shaders, ConstantAndDefaultSurfaceNeedNoLights) {
  Fixture f;
  auto constant = make_surface_shader("constant", {}, {}, f.diag);
  ShadingPoint sp = facing_up();
  sp.Os = {0.5f, 0.5f, 0.5f};
  ShadeResult r = shade_unshadowed(*constant, sp, {});
  EXPECT_NEAR(r.Ci.x, 0.25f, 1e-6f) << "Ci = Os * Cs";
  auto def = make_surface_shader("defaultsurface", {}, {}, f.diag);
  EXPECT_NEAR(shade_unshadowed(*def, facing_up(), {}).Ci.x, 0.5f, 1e-6f) << "head-on: Ka + Kd = 1";
}

TEST(Shaders, UnknownNamesWarnOnceAndFallBack) {
  int warnings = 0;
  Diagnostics diag([&](const Diagnostic& d) { warnings += d.severity == Severity::Warning; });
  auto a = make_surface_shader("show_st", {}, {}, diag);
  auto b = make_surface_shader("show_st", {}, {}, diag);
  EXPECT_EQ(warnings, 1);
  EXPECT_NEAR(shade_unshadowed(*a, facing_up(), {}).Ci.x, 0.5f, 1e-6f) << "defaultsurface";
  auto lights = make_lights({light("studio_spot", params({{"from", {0, 1, 0}}, {"to", {0, 0, 0}}, {"coneangle", {0.5f}}}))},
                            diag);
  EXPECT_EQ(warnings, 2);
  LightContribution lc;
  EXPECT_TRUE(lights[0]->illuminate({0, 0, 0}, lc)) << "falls back to a spotlight";
}

}  // namespace
}  // namespace darc

namespace darc {
namespace {

TEST(Shaders, DielectricFresnelAtNormalIncidenceGrazingAndPastTheCriticalAngle) {
  EXPECT_NEAR(dielectric_fresnel(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f) << "((n1 - n2) / (n1 + n2))^2";
  EXPECT_NEAR(dielectric_fresnel(1.0f, 1.5f), 0.04f, 1e-6f) << "the same leaving the glass";
  EXPECT_EQ(dielectric_fresnel(0.7f, 1.0f), 0.0f) << "no interface";
  EXPECT_NEAR(dielectric_fresnel(0.0f, 1.0f / 1.5f), 1.0f, 1e-6f) << "grazing";
  EXPECT_EQ(dielectric_fresnel(0.5f, 1.5f), 1.0f) << "60 degrees inside glass: total internal reflection";
}

TEST(Shaders, MirrorGlassAndShinymetalDescribeTheirTracedRays) {
  Diagnostics diag([](const Diagnostic&) {});
  ShadingPoint sp;
  sp.N = {0, 1, 0};
  sp.I = {0, -1, 0};
  sp.Cs = {0.5f, 0.25f, 1.0f};
  sp.Os = {1, 1, 1};
  SurfaceLobes mirror = make_surface_shader("mirror", {}, {}, diag)->lobes(sp);
  EXPECT_EQ(mirror.reflection, (Vec3f{1, 1, 1})) << "Kr = 1";
  EXPECT_EQ(mirror.transmission, (Vec3f{}));
  EXPECT_EQ(mirror.ambient, (Vec3f{})) << "Ka = 0";
  SurfaceLobes shiny = make_surface_shader("shinymetal", {}, {}, diag)->lobes(sp);
  EXPECT_EQ(shiny.reflection, sp.Cs) << "Kr * Cs";
  SurfaceLobes metal = make_surface_shader("metal", {}, {}, diag)->lobes(sp);
  EXPECT_EQ(metal.reflection, (Vec3f{})) << "RI metal has no Kr";
  SurfaceLobes glass = make_surface_shader("glass", {}, {}, diag)->lobes(sp);
  EXPECT_NEAR(glass.reflection.x, 0.04f, 1e-6f) << "Kr * F at normal incidence";
  EXPECT_NEAR(glass.transmission.x, 0.96f, 1e-6f) << "Kt * (1 - F)";
  EXPECT_NEAR(glass.eta, 1.0f / 1.5f, 1e-7f) << "entering";
  sp.N = {0, -1, 0};  // seen from inside
  SurfaceLobes leaving = make_surface_shader("glass", {}, {}, diag)->lobes(sp);
  EXPECT_NEAR(leaving.eta, 1.5f, 1e-7f);
  EXPECT_EQ(leaving.Nf, (Vec3f{0, 1, 0})) << "reflection and refraction about the normal facing the ray";
}

}  // namespace
}  // namespace darc
