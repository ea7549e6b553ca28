// RenderMan 21+ (RIS) requests in SceneBuilder: each Bxdf and Light mapping gives the darc
// material and light values RenderMan's parameters call for, what is dropped is warned once,
// unknown names fall back, patterns give their colour, Integrator is recorded.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/scene/ris/ris_patterns.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

std::vector<Diagnostic> of(const Built& b, Severity s) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == s) out.push_back(d);
  return out;
}
std::vector<Diagnostic> warnings(const Built& b) { return of(b, Severity::Warning); }
std::vector<Diagnostic> errors(const Built& b) { return of(b, Severity::Error); }
// The warnings of one request (a world without geometry also gets one of its own).
std::vector<Diagnostic> warnings(const Built& b, const std::string& request) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : warnings(b))
    if (d.request == request) out.push_back(d);
  return out;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The material of the first sphere of a world block holding `body` then a sphere.
Material sphere_material(const std::string& body, Built* out = nullptr) {
  Built b = build("WorldBegin\n" + body + "\nSphere 1 -1 1 360\nWorldEnd\n");
  EXPECT_TRUE(errors(b).empty()) << errors(b)[0].str();
  if (b.scenes.size() != 1 || b.scenes[0].surfaces.spheres.empty()) {
    ADD_FAILURE() << "no sphere";
    return {};
  }
  Material m = b.scenes[0].materials[b.scenes[0].surfaces.sphere_material[0]];
  if (out) *out = std::move(b);
  return m;
}

float param(const ParamList& p, const char* name) {
  const Param* x = p.find(name);
  EXPECT_TRUE(x) << name;
  return x && !x->floats.empty() ? x->floats[0] : NAN;
}

Vec3f param3(const ParamList& p, const char* name) {
  const Param* x = p.find(name);
  EXPECT_TRUE(x && x->floats.size() == 3) << name;
  return x && x->floats.size() == 3 ? Vec3f{x->floats[0], x->floats[1], x->floats[2]} : Vec3f{NAN, NAN, NAN};
}

TEST(RisBxdf, PxrSurfaceIsPlasticWithItsDiffuseAndSpecularColoursAndGains) {
  const Material m = sphere_material(
      R"(Bxdf "PxrSurface" "s" "color diffuseColor" [0.8 0.2 0.1] "float diffuseGain" [0.5]
         "color specularFaceColor" [0.3 0.4 0.5] "float specularRoughness" [0.05])");
  EXPECT_EQ(m.surface, "plastic");
  EXPECT_EQ(m.color, (Vec3f{0.8f, 0.2f, 0.1f})) << "the diffuse colour is Cs";
  EXPECT_EQ(param(m.surface_params, "Kd"), 0.5f);
  EXPECT_EQ(param(m.surface_params, "Ka"), 0.5f);
  EXPECT_EQ(param(m.surface_params, "Ks"), 1.0f);
  EXPECT_EQ(param(m.surface_params, "roughness"), 0.05f);
  EXPECT_EQ(param3(m.surface_params, "specularcolor"), (Vec3f{0.3f, 0.4f, 0.5f}));
}

TEST(RisBxdf, PxrSurfaceDefaultsAreRenderMans) {
  const Material m = sphere_material(R"(Bxdf "PxrSurface" "s")");
  EXPECT_EQ(m.color, (Vec3f{0.18f, 0.18f, 0.18f}));
  EXPECT_EQ(param(m.surface_params, "Kd"), 1.0f);
  EXPECT_EQ(param(m.surface_params, "roughness"), 0.2f);
  EXPECT_EQ(param3(m.surface_params, "specularcolor"), (Vec3f{0, 0, 0})) << "no specular unless a face colour is given";
}

TEST(RisBxdf, PxrDisneyIsPlasticWithItsBaseColourAndTintedSpecular) {
  const Material m = sphere_material(
      R"(Bxdf "PxrDisney" "d" "color baseColor" [0.5 0.25 1] "float specular" [0.7] "float roughness" [0.3]
         "float specularTint" [1])");
  EXPECT_EQ(m.surface, "plastic");
  EXPECT_EQ(m.color, (Vec3f{0.5f, 0.25f, 1.0f}));
  EXPECT_EQ(param(m.surface_params, "Ks"), 0.7f);
  EXPECT_EQ(param(m.surface_params, "roughness"), 0.3f);
  // Fully tinted: the base colour over its luminance 0.3*0.5 + 0.6*0.25 + 0.1*1 = 0.4.
  const Vec3f s = param3(m.surface_params, "specularcolor");
  EXPECT_FLOAT_EQ(s.x, 1.25f);
  EXPECT_FLOAT_EQ(s.y, 0.625f);
  EXPECT_FLOAT_EQ(s.z, 2.5f);
}

TEST(RisBxdf, PxrDiffuseIsMatteAndPxrConstantIsConstant) {
  const Material d = sphere_material(R"(Bxdf "PxrDiffuse" "d" "color diffuseColor" [0.1 0.2 0.3])");
  EXPECT_EQ(d.surface, "matte");
  EXPECT_EQ(d.color, (Vec3f{0.1f, 0.2f, 0.3f}));
  EXPECT_EQ(sphere_material(R"(Bxdf "PxrDiffuse" "d")").color, (Vec3f{0.5f, 0.5f, 0.5f}));
  const Material c = sphere_material(R"(Bxdf "PxrConstant" "c" "color emitColor" [2 1 0])");
  EXPECT_EQ(c.surface, "constant");
  EXPECT_EQ(c.color, (Vec3f{2, 1, 0}));
}

TEST(RisBxdf, AColorAfterTheBxdfOverridesItsColourAsForSurface) {
  const Material m = sphere_material("Bxdf \"PxrDiffuse\" \"d\" \"color diffuseColor\" [0.1 0.2 0.3]\nColor 1 0 0");
  EXPECT_EQ(m.color, (Vec3f{1, 0, 0}));
}

TEST(RisBxdf, DroppedParametersAreWarnedOncePerDistinctRequest) {
  Built b;
  sphere_material(R"(Bxdf "PxrSurface" "a" "float clearcoatGain" [1] "float diffuseGain" [1] "color glowColor" [1 1 1]
Bxdf "PxrSurface" "b" "float clearcoatGain" [0.5] "color glowColor" [0 0 0]
Bxdf "PxrSurface" "c" "float presence" [1])",
                  &b);
  const auto w = warnings(b);
  ASSERT_EQ(w.size(), 2u) << "the second request drops the same parameters";
  EXPECT_EQ(w[0].request, "Bxdf");
  EXPECT_EQ(w[0].message, "PxrSurface is mapped to darc's plastic: dropped clearcoatGain, glowColor");
  EXPECT_EQ(w[1].message, "PxrSurface is mapped to darc's plastic: dropped presence");
  EXPECT_EQ(w[0].loc.line, 2);
}

TEST(RisBxdf, AnUnknownBxdfWarnsAndIsDefaultsurfaceKeepingCs) {
  Built b;
  const Material m = sphere_material(
      "Color 0.2 0.4 0.6\nBxdf \"PxrLayerSurface\" \"l\" \"float x\" [1]\n"
      "Bxdf \"PxrLayerSurface\" \"l2\"",
      &b);
  EXPECT_EQ(m.surface, "defaultsurface");
  EXPECT_EQ(m.color, (Vec3f{0.2f, 0.4f, 0.6f}));
  const auto w = warnings(b);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].message, "unknown Bxdf \"PxrLayerSurface\": using defaultsurface");
}

TEST(RisBxdf, OutOfRangeValuesAreClampedAsForSurface) {
  Built b;
  const Material m = sphere_material(R"(Bxdf "PxrSurface" "s" "float diffuseGain" [-1])", &b);
  EXPECT_EQ(param(m.surface_params, "Kd"), 0.0f);
  ASSERT_FALSE(warnings(b).empty());
}

TEST(RisPattern, MelaninColourIsWhiteWithoutMelaninAndDarkensWithIt) {
  EXPECT_EQ(melanin_hair_color(0, 0.5f), (Vec3f{1, 1, 1}));
  Vec3f previous{1, 1, 1};
  for (float m : {0.2f, 0.4f, 0.6f, 0.8f, 1.0f}) {
    const Vec3f c = melanin_hair_color(m, 0.3f);
    EXPECT_LT(c.x, previous.x);
    EXPECT_LT(c.z, previous.z);
    EXPECT_GE(c.x, c.y) << "melanin absorbs blue most: hair is warm";
    EXPECT_GE(c.y, c.z);
    previous = c;
  }
  EXPECT_LT(melanin_hair_color(1, 0).x, 1e-4f) << "full melanin is black";
  // Chiang et al.'s inverse: colour = exp(-sqrt(sigma) * 5.8893) with sigma = -ln(1 - m) * the
  // eumelanin coefficients (no redness).
  const float amount = -std::log(1 - 0.5f);
  EXPECT_NEAR(melanin_hair_color(0.5f, 0).x, std::exp(-std::sqrt(amount * 0.506f) * 5.8893f), 1e-4f);
  const Vec3f eu = melanin_hair_color(0.5f, 0), pheo = melanin_hair_color(0.5f, 1);
  EXPECT_GT(pheo.x / pheo.z, 1.0f);
  EXPECT_GT(pheo.x, eu.x) << "pheomelanin absorbs less red";
}

TEST(RisPattern, PxrHairColorDrivesTheHairShadersColour) {
  Built b;
  const Material m = sphere_material(R"(Pattern "PxrHairColor" "hc" "float melanin" [0.4] "float melaninRedness" [0.7]
Bxdf "PxrMarschnerHair" "h" "reference color diffuseColor" ["hc:resultDiffuse"] "float diffuseGain" [0.8]
  "float specularGainR" [0.5] "color specularColorR" [1 0.9 0.8] "float specularConeAngleR" [60])",
                                     &b);
  // Onto the Chiang et al. fibre: the colour as Cs (chianghair inverts it to an absorption), the R
  // cone's angle as chianghair's coneangle, RenderMan's default offset (-3 degrees) as the
  // scales' tilt (+3) and its default index.
  EXPECT_EQ(m.surface, "chianghair");
  EXPECT_EQ(m.color, melanin_hair_color(0.4f, 0.7f));
  EXPECT_EQ(param(m.surface_params, "coneangle"), 60.0f);
  EXPECT_EQ(param(m.surface_params, "alpha"), 3.0f);
  EXPECT_EQ(param(m.surface_params, "eta"), 1.55f);
  // The per-lobe gains and colours have no place in an energy-conserving fibre: said once.
  const auto w = warnings(b);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_TRUE(contains(w[0].message, "diffuseGain")) << w[0].message;
  EXPECT_TRUE(contains(w[0].message, "specularGainR")) << w[0].message;
  EXPECT_TRUE(contains(w[0].message, "specularColorR")) << w[0].message;
}

TEST(RisPattern, AHairColourThroughTheSpecularInputsOnlyStillColoursTheHair) {
  const Material m = sphere_material(R"(Pattern "PxrHairColor" "hc" "float melanin" [0.6]
Bxdf "PxrMarschnerHair" "h" "reference color specularColorTRT" ["hc:resultTRT"])");
  EXPECT_EQ(m.color, melanin_hair_color(0.6f, 0.5f)) << "with darc's default redness";
}

TEST(RisPattern, AConstantColourPatternGivesItsColour) {
  const Material m = sphere_material(R"(Pattern "MyColor" "c" "color value" [0.3 0.6 0.9]
Bxdf "PxrDiffuse" "d" "reference color diffuseColor" ["c:resultRGB"])");
  EXPECT_EQ(m.color, (Vec3f{0.3f, 0.6f, 0.9f}));
}

TEST(RisPattern, OtherPatternsWarnOnceAndTheBxdfKeepsItsDefaultColour) {
  Built b;
  // (A PxrTexture is evaluated: RisBxdf.APxrTextureFeedingTheColour... below.)
  const Material m = sphere_material(R"(Pattern "PxrChecker" "tex" "float frequency" [8]
Bxdf "PxrSurface" "s" "reference color diffuseColor" ["tex:resultRGB"]
Bxdf "PxrSurface" "s2" "reference color diffuseColor" ["tex:resultRGB"]
Bxdf "PxrSurface" "s3" "reference color diffuseColor" ["nowhere:resultRGB"] "reference float diffuseGain" ["tex:resultR"])",
                                     &b);
  EXPECT_EQ(m.color, (Vec3f{0.18f, 0.18f, 0.18f}));
  EXPECT_EQ(param(m.surface_params, "Kd"), 1.0f);
  const auto w = warnings(b);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].message,
            "PxrSurface: \"diffuseColor\" (Pattern \"tex\" is a PxrChecker, which darc does not evaluate) keeps its "
            "default colour");
  EXPECT_TRUE(contains(w[1].message, "no Pattern \"nowhere\"")) << w[1].message;
  EXPECT_TRUE(contains(w[2].message, "\"diffuseGain\"")) << w[2].message;
}

TEST(RisPattern, PxrHairColorInputsOtherThanMelaninAreWarned) {
  Built b;
  build(
      "WorldBegin\nPattern \"PxrHairColor\" \"a\" \"float melanin\" [0.2] \"float dyeHue\" [0.5]\n"
      "Pattern \"PxrHairColor\" \"b\" \"float dyeHue\" [0.1]\nWorldEnd\n")
      .diagnostics.swap(b.diagnostics);
  ASSERT_EQ(warnings(b, "Pattern").size(), 1u);
  EXPECT_EQ(warnings(b, "Pattern")[0].message, "PxrHairColor is read for its melanin colour only: dropped dyeHue");
}

// --- lights ---

const LightDesc& only_light(const Built& b) {
  EXPECT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes.at(0).lights.size(), 1u);
  return b.scenes.at(0).lights.at(0);
}

Built world(const std::string& body) { return build("WorldBegin\n" + body + "\nWorldEnd\n"); }

TEST(RisLight, PxrDistantLightIsADistantLightAlongPlusZWithIntensityExposureAndColour) {
  Built b = world(R"(Rotate 90 0 1 0
Light "PxrDistantLight" "sun" "float intensity" [3] "float exposure" [2] "color lightColor" [1 0.5 0.25])");
  const LightDesc& l = only_light(b);
  EXPECT_EQ(l.shader, "distantlight");
  EXPECT_EQ(param(l.params, "intensity"), 12.0f) << "3 * 2^2";
  EXPECT_EQ(param3(l.params, "lightcolor"), (Vec3f{1, 0.5f, 0.25f}));
  const Vec3d from = l.shader_to_world.transform_point(Vec3d(param3(l.params, "from")));
  const Vec3d to = l.shader_to_world.transform_point(Vec3d(param3(l.params, "to")));
  const Vec3d dir = to - from;  // Rotate 90 about y takes +z to +x: RenderMan's lights shine along their +z
  EXPECT_NEAR(dir.x, 1, 1e-9);
  EXPECT_NEAR(dir.y, 0, 1e-9);
  EXPECT_NEAR(dir.z, 0, 1e-9);
  EXPECT_TRUE(l.casts_shadows) << "RenderMan lights cast shadows unless enableShadows is 0";
  EXPECT_FALSE(only_light(world(R"(Light "PxrDistantLight" "s" "int enableShadows" [0])")).casts_shadows);
}

TEST(RisLight, PxrSphereLightIsASphereLightOfItsRadiance) {
  Built b = world(R"(Translate 1 2 3 Scale 3 3 3
Light "PxrSphereLight" "bulb" "float intensity" [2])");
  const LightDesc& l = only_light(b);
  EXPECT_EQ(l.shader, "spherelight");
  EXPECT_EQ(param(l.params, "intensity"), 2.0f);
  EXPECT_TRUE(warnings(b, "Light").empty()) << "not an approximation any more";
  // With areaNormalize the radiance is divided by the area 4 pi r^2 (r = 0.5 * 3).
  Built normalized = world(R"(Scale 3 3 3
Light "PxrSphereLight" "bulb" "float intensity" [2] "int areaNormalize" [1])");
  EXPECT_NEAR(param(only_light(normalized).params, "intensity"), 2 / (4 * std::numbers::pi * 1.5 * 1.5), 1e-6);
}

TEST(RisLight, PxrRectAndDiskLightsAreAreaLightsOfTheirRadiance) {
  Built b = world(R"(Scale 2 3 1
Light "PxrRectLight" "key" "float intensity" [0.5] "float exposure" [-1])");
  const LightDesc& l = only_light(b);
  EXPECT_EQ(l.shader, "rectlight");
  EXPECT_NEAR(param(l.params, "intensity"), 0.25, 1e-6) << "the radiance, whatever the size";
  EXPECT_TRUE(warnings(b, "Light").empty()) << "not an approximation any more";
  Built disk = world(R"(Scale 2 2 1
Light "PxrDiskLight" "fill" "float intensity" [3] "int areaNormalize" [1])");
  EXPECT_EQ(only_light(disk).shader, "disklight");
  EXPECT_NEAR(param(only_light(disk).params, "intensity"), 3 / std::numbers::pi, 1e-6) << "over the area pi";
}

TEST(RisLight, PxrDomeLightIsADomeLightWithShadowsAndItsMapAMapname) {
  Built b = world(R"(Light "PxrDomeLight" "env" "float exposure" [1] "string lightColorMap" ["sky.tex"])");
  const LightDesc& l = only_light(b);
  EXPECT_EQ(l.shader, "domelight");
  EXPECT_EQ(param(l.params, "intensity"), 2.0f);
  EXPECT_TRUE(l.casts_shadows);
  const Param* map = l.params.find("mapname");
  ASSERT_NE(map, nullptr);
  ASSERT_EQ(map->strings.size(), 1u);
  EXPECT_EQ(map->strings[0], "") << "not found: cleared, so the dome keeps its colour";
  const auto w = warnings(b, "Light");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].message.find("texture \"sky.tex\" not found"), std::string::npos) << w[0].message;
  EXPECT_NE(w[0].message.find("domelight lights with its colour alone"), std::string::npos) << w[0].message;
}

TEST(RisBxdf, APxrTextureFeedingTheColourBecomesTheSurfacesColourTexture) {
  Built b = world(R"(Pattern "PxrManifold2D" "m" "float scaleS" [4] "float offsetT" [0.25] "int invertT" [0]
Pattern "PxrTexture" "t" "string filename" ["wood.tex"] "int invertT" [0] "int linearize" [1] "float blur" [0.1] "reference struct manifold" ["m:result"]
Bxdf "PxrSurface" "s" "reference color diffuseColor" ["t:resultRGB"]
Sphere 1 -1 1 360)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Material& m = b.scenes[0].materials.back();
  EXPECT_EQ(m.surface, "plastic");
  EXPECT_EQ(m.color, (Vec3f{1, 1, 1})) << "Cs 1, times the texture";
  const Param* file = m.surface_params.find("__colortexture");
  ASSERT_NE(file, nullptr);
  EXPECT_EQ(file->strings, std::vector<std::string>{""}) << "wood.tex is not found here: cleared";
  const Param* manifold = m.surface_params.find("__colortexture_manifold");
  ASSERT_NE(manifold, nullptr);
  EXPECT_EQ(manifold->floats, (std::vector<float>{4, 1, 0, 0.25f, 0, 0})) << "both invertT 0: t as it is";
  EXPECT_EQ(m.surface_params.get_float("__colortexture_linearize", 0), 1.0f);
  bool dropped_blur = false, not_found = false;
  for (const Diagnostic& d : warnings(b)) {
    dropped_blur |= d.message.find("diffuseColor's PxrTexture blur") != std::string::npos;
    not_found |= d.message.find("texture \"wood.tex\" not found") != std::string::npos;
  }
  EXPECT_TRUE(dropped_blur);
  EXPECT_TRUE(not_found);
}

TEST(RisLight, FixedSampleCountIsTheLightsSampleCountAndZeroLeavesDarcsDefault) {
  Built b = world(R"(Light "PxrRectLight" "key" "int fixedSampleCount" [64])");
  EXPECT_EQ(param(only_light(b).params, "nsamples"), 64.0f);
  EXPECT_TRUE(warnings(b, "Light").empty()) << "read, not dropped";
  Built automatic = world(R"(Light "PxrDomeLight" "env" "int fixedSampleCount" [0])");
  EXPECT_EQ(only_light(automatic).params.find("nsamples"), nullptr);
}

TEST(RisLight, AnUnknownLightWarnsMakesNoLightAndItsHandleStaysValid) {
  Built b = world(R"(Light "PxrMeshLight" "mesh" "float intensity" [3]
Illuminate "mesh" 0
Sphere 1 -1 1 360)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(b.scenes[0].lights.empty());
  EXPECT_TRUE(errors(b).empty()) << errors(b)[0].str();
  ASSERT_EQ(warnings(b).size(), 1u);
  EXPECT_EQ(warnings(b)[0].message, "unknown Light \"PxrMeshLight\": no light");
}

TEST(RisLight, IlluminateSwitchesARisLightAsALightSource) {
  Built b = world(R"(Light "PxrDistantLight" "sun"
LightSource "pointlight" "lamp"
AttributeBegin
  Illuminate "sun" 0
  Sphere 1 -1 1 360
AttributeEnd
Sphere 2 -1 1 360)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[0]].lights, (std::vector<uint32_t>{1}));
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[1]].lights, (std::vector<uint32_t>{0, 1}));
}

TEST(RisLight, ALightInItsOwnAttributeBlockStillLightsWhatFollows) {
  Built b = world(R"(AttributeBegin
  AttributeBegin
    Translate 0 5 0
    Light "PxrSphereLight" "bulb"
  AttributeEnd
  Sphere 1 -1 1 360
AttributeEnd
Sphere 2 -1 1 360
LightSource "pointlight" "lamp"
AttributeBegin
  Illuminate "bulb" 0
  Sphere 3 -1 1 360
AttributeEnd
AttributeBegin
  LightSource "pointlight" "scoped"
AttributeEnd
Sphere 4 -1 1 360)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  ASSERT_EQ(s.lights.size(), 3u);
  ASSERT_EQ(s.surfaces.spheres.size(), 4u);
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[0]].lights, (std::vector<uint32_t>{0}));
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[1]].lights, (std::vector<uint32_t>{0}))
      << "RIS: a light is a scene object";
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[2]].lights, (std::vector<uint32_t>{1}))
      << "Illuminate still switches it";
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[3]].lights, (std::vector<uint32_t>{0, 1}))
      << "a LightSource keeps the RI rule: off after its AttributeEnd";
}

TEST(RisIntegrator, TheIntegratorIsRecordedForTheFrameAndIgnoredInsideTheWorld) {
  Built b = build(R"(Integrator "PxrPathTracer" "pt" "int maxPathLength" [5]
WorldBegin
Integrator "PxrVCM" "vcm"
WorldEnd
WorldBegin
WorldEnd
)");
  ASSERT_EQ(b.scenes.size(), 2u);
  EXPECT_EQ(b.scenes[0].output.integrator, "PxrPathTracer");
  EXPECT_EQ(b.scenes[1].output.integrator, "PxrPathTracer");
  bool ignored_in_world = false;
  for (const Diagnostic& d : warnings(b))
    if (d.request == "Integrator" && contains(d.message, "options cannot change")) ignored_in_world = true;
  EXPECT_TRUE(ignored_in_world);
  EXPECT_TRUE(build("WorldBegin\nWorldEnd\n").scenes[0].output.integrator.empty());
}

TEST(RisRequests, InsideAnObjectTheyAreReplayedAtEachInstance) {
  Built b = build(R"(WorldBegin
ObjectBegin "ball"
  Bxdf "PxrDiffuse" "d" "color diffuseColor" [0.1 0.2 0.3]
  Sphere 1 -1 1 360
ObjectEnd
ObjectInstance "ball"
WorldEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u);
  ASSERT_EQ(b.scenes[0].surfaces.spheres.size(), 1u);
  EXPECT_EQ(b.scenes[0].materials[b.scenes[0].surfaces.sphere_material[0]].surface, "matte");
}

}  // namespace
}  // namespace darc
