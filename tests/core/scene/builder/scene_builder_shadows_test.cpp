// SceneBuilder and the RIB conventions for ray tracing: which lights cast shadows ("shadowname",
// Attribute "light" "shadows") and what blocks their light (Attribute "visibility"
// "transmission", Attribute "render" "casts_shadows"), and Option "trace" "maxdepth".
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

// The diagnostics of one severity whose message contains `text`.
std::vector<Diagnostic> reported(const Built& b, Severity severity, const std::string& text) {
  std::vector<Diagnostic> found;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == severity && d.message.find(text) != std::string::npos) found.push_back(d);
  return found;
}

// The diagnostics about the requests, without the frame-level "nothing renderable" warning
// (most scenes here hold lights and no geometry).
std::vector<Diagnostic> scene_notes(const Built& b) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : b.diagnostics)
    if (d.message.find("nothing renderable") == std::string::npos) out.push_back(d);
  return out;
}

// casts_shadows of each light of the only scene, in declaration order.
std::vector<bool> shadows(const Built& b) {
  std::vector<bool> out;
  if (b.scenes.size() != 1) return out;
  for (const LightDesc& l : b.scenes[0].lights) out.push_back(l.casts_shadows);
  return out;
}

TEST(SceneBuilderShadows, ShadownameRaytraceCastsShadows) {
  Built b = build("WorldBegin\nLightSource \"spotlight\" 1 \"shadowname\" [\"raytrace\"]\nWorldEnd\n");
  EXPECT_EQ(shadows(b), std::vector<bool>{true});
  EXPECT_TRUE(scene_notes(b).empty()) << "a predeclared parameter, and no shadow-map warning";
}

TEST(SceneBuilderShadows, ShadowMapFilesAreTracedWithOneWarning) {
  Built b = build(R"(WorldBegin
LightSource "spotlight" "key" "string shadowname" ["key.shad"]
LightSource "spotlight" "fill" "shadowname" "fill.shad"
WorldEnd
)");
  EXPECT_EQ(shadows(b), (std::vector<bool>{true, true}));
  const std::vector<Diagnostic> w = reported(b, Severity::Warning, "shadow maps are not supported");
  ASSERT_EQ(w.size(), 1u) << "one warning per run, however many lights";
  EXPECT_EQ(w[0].message,
            "shadow maps are not supported: light \"key\" uses ray-traced shadows instead of \"key.shad\"");
  EXPECT_EQ(w[0].loc.line, 2);
  EXPECT_EQ(scene_notes(b).size(), 1u);
}

TEST(SceneBuilderShadows, EmptyOrMissingShadownameCastsNone) {
  Built b =
      build("WorldBegin\nLightSource \"spotlight\" 1 \"shadowname\" [\"\"]\nLightSource \"pointlight\" 2\nWorldEnd\n");
  EXPECT_EQ(shadows(b), (std::vector<bool>{false, false}));
  EXPECT_TRUE(scene_notes(b).empty());
}

TEST(SceneBuilderShadows, ShadownameMustBeAString) {
  Built b = build("WorldBegin\nLightSource \"spotlight\" 1 \"float shadowname\" [1]\nWorldEnd\n");
  ASSERT_EQ(b.scenes.size(), 1u) << "the frame is built without the bad request";
  EXPECT_TRUE(b.scenes[0].lights.empty());
  EXPECT_EQ(b.frame_errors[0].count, 1);
  const std::vector<Diagnostic> e = reported(b, Severity::Error, "\"shadowname\" must be a string");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].loc.line, 2);
}

TEST(SceneBuilderShadows, LightShadowsAttributeIsScopedByAttributeBlocks) {
  Built b = build(R"(WorldBegin
LightSource "pointlight" 1
AttributeBegin
  Attribute "light" "string shadows" ["on"]
  LightSource "pointlight" 2
  AttributeBegin
    Attribute "light" "shadows" "off"
    LightSource "pointlight" 3
    LightSource "pointlight" 4 "shadowname" "raytrace"
  AttributeEnd
  LightSource "pointlight" 5
AttributeEnd
LightSource "pointlight" 6
WorldEnd
)");
  EXPECT_EQ(shadows(b), (std::vector<bool>{false, true, false, true, true, false}))
      << "either convention turning shadows on is enough";
  EXPECT_TRUE(scene_notes(b).empty());
}

TEST(SceneBuilderShadows, LightShadowsValueOtherThanOnOrOffIsAnError) {
  Built b = build(R"(WorldBegin
Attribute "light" "string shadows" ["yes"]
Attribute "light" "shadows" [1]
LightSource "pointlight" 1
WorldEnd
)");
  EXPECT_EQ(shadows(b), std::vector<bool>{false}) << "the frame is built; the bad values changed nothing";
  EXPECT_EQ(b.frame_errors[0].count, 2);
  std::vector<Diagnostic> e = reported(b, Severity::Error, "Attribute \"light\" \"shadows\" must be");
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].message, "Attribute \"light\" \"shadows\" must be \"on\" or \"off\", found \"yes\"");
  EXPECT_EQ(e[0].request, "Attribute");
  EXPECT_EQ(e[0].loc.line, 2);
  EXPECT_EQ(e[1].loc.line, 3) << "a number is an error too";
}

TEST(SceneBuilderShadows, PreWorldLightsKeepTheirShadows) {
  Built b = build(R"(LightSource "distantlight" 1 "shadowname" "raytrace"
Attribute "light" "shadows" "on"
LightSource "distantlight" 2
Attribute "light" "shadows" "off"
LightSource "distantlight" 3
WorldBegin
LightSource "pointlight" 4
WorldEnd
)");
  EXPECT_EQ(shadows(b), (std::vector<bool>{true, true, false, false}));
}

TEST(SceneBuilderShadows, ObjectInstancesReplayTheLightAttribute) {
  Built b = build(R"(WorldBegin
ObjectBegin "lamp"
  Attribute "light" "shadows" "on"
  LightSource "pointlight" 1
ObjectEnd
ObjectInstance "lamp"
LightSource "pointlight" 2
WorldEnd
)");
  EXPECT_EQ(shadows(b), (std::vector<bool>{true, false})) << "the object's attributes end with it";
}

TEST(SceneBuilderShadows, OtherLightParametersWarnOncePerName) {
  Built b = build(R"(WorldBegin
Attribute "light" "integer nsamples" [4]
Attribute "light" "integer nsamples" [8] "string shadows" ["on"]
Attribute "identifier" "name" ["a"]
Attribute "identifier" "name" ["b"]
WorldEnd
)");
  ASSERT_EQ(scene_notes(b).size(), 2u);
  EXPECT_EQ(scene_notes(b)[0].message, "Attribute \"light\" \"nsamples\" has no effect in darc: ignored");
  EXPECT_EQ(scene_notes(b)[1].message, "Attribute \"identifier\" has no effect in darc: ignored")
      << "categories darc does not read at all still warn once per category";
}

// The transmission of the material of a sphere made after `attributes`.
struct TransmissionCase {
  const char* attributes;
  Transmission expected;
};

class SceneBuilderTransmission : public testing::TestWithParam<TransmissionCase> {};

TEST_P(SceneBuilderTransmission, SpellingGivesTheMaterialsTransmission) {
  const TransmissionCase& c = GetParam();
  Built b = build(std::string("WorldBegin\n") + c.attributes + "\nSphere 1 -1 1 360\nWorldEnd\n");
  ASSERT_EQ(b.scenes.size(), 1u) << c.attributes;
  const Scene& s = b.scenes[0];
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[0]].transmission, c.expected) << c.attributes;
  EXPECT_TRUE(reported(b, Severity::Warning, "no effect").empty()) << c.attributes;
}

INSTANTIATE_TEST_SUITE_P(
    EverySpelling, SceneBuilderTransmission,
    testing::Values(
        TransmissionCase{"", Transmission::Os},
        TransmissionCase{"Attribute \"visibility\" \"int transmission\" [1]", Transmission::Os},
        TransmissionCase{"Attribute \"visibility\" \"int transmission\" [0]", Transmission::Transparent},
        TransmissionCase{"Attribute \"visibility\" \"transmission\" 0", Transmission::Transparent},
        TransmissionCase{"Attribute \"visibility\" \"string transmission\" [\"opaque\"]", Transmission::Opaque},
        TransmissionCase{"Attribute \"visibility\" \"string transmission\" [\"transparent\"]",
                         Transmission::Transparent},
        TransmissionCase{"Attribute \"visibility\" \"string transmission\" [\"Os\"]", Transmission::Os},
        TransmissionCase{"Attribute \"visibility\" \"string transmission\" [\"shader\"]", Transmission::Os},
        TransmissionCase{"Attribute \"render\" \"string casts_shadows\" [\"none\"]", Transmission::Transparent},
        TransmissionCase{"Attribute \"render\" \"string casts_shadows\" [\"opaque\"]", Transmission::Opaque},
        TransmissionCase{"Attribute \"render\" \"string casts_shadows\" [\"Os\"]", Transmission::Os},
        TransmissionCase{"Attribute \"render\" \"casts_shadows\" \"shade\"", Transmission::Os},
        TransmissionCase{"Attribute \"render\" \"casts_shadows\" \"none\"\n"
                         "Attribute \"visibility\" \"transmission\" \"opaque\"",
                         Transmission::Opaque}));

TEST(SceneBuilderShadows, ShaderOpacitySpellingsWarnOnce) {
  Built b = build(R"(WorldBegin
Attribute "visibility" "string transmission" ["shader"]
Sphere 1 -1 1 360
Attribute "render" "string casts_shadows" ["shade"]
Sphere 1 -1 1 360
WorldEnd
)");
  ASSERT_EQ(scene_notes(b).size(), 1u);
  EXPECT_EQ(scene_notes(b)[0].message, "shader-computed opacity is not run for shadows: Os is used");
  EXPECT_EQ(scene_notes(b)[0].loc.line, 2);
}

TEST(SceneBuilderShadows, UnknownTransmissionValuesAreErrorsNamingTheAcceptedOnes) {
  Built b = build(R"(WorldBegin
Attribute "visibility" "string transmission" ["glass"]
Attribute "render" "string casts_shadows" ["all"]
Attribute "visibility" "int transmission" [2]
Attribute "render" "casts_shadows" [1]
WorldEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u) << "the frame is built without the bad requests";
  EXPECT_EQ(b.frame_errors[0].count, 4);
  std::vector<Diagnostic> e;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error && d.request == "Attribute") e.push_back(d);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[0].message,
            "Attribute \"visibility\" \"transmission\" must be one of \"opaque\", \"transparent\", \"Os\", \"shader\", "
            "found \"glass\"");
  EXPECT_EQ(e[0].loc.line, 2);
  EXPECT_EQ(e[1].message,
            "Attribute \"render\" \"casts_shadows\" must be one of \"none\", \"opaque\", \"Os\", \"shade\", found "
            "\"all\"");
  EXPECT_EQ(e[1].loc.line, 3);
  EXPECT_EQ(e[2].message,
            "Attribute \"visibility\" \"transmission\" must be 0 or 1 (or one of \"opaque\", \"transparent\", \"Os\", "
            "\"shader\"), found 2");
  EXPECT_EQ(e[2].loc.line, 4);
  EXPECT_NE(e[3].message.find("\"casts_shadows\" must be a string"), std::string::npos) << e[3].message;
  EXPECT_EQ(e[3].loc.line, 5);
}

TEST(SceneBuilderShadows, OtherVisibilityParametersWarnOncePerName) {
  Built b = build(R"(WorldBegin
Attribute "visibility" "int camera" [0] "int transmission" [0]
Attribute "visibility" "int camera" [1] "int diffuse" [1]
Attribute "render" "string casts_shadows" ["opaque"] "integer visibility" [7]
Sphere 1 -1 1 360
WorldEnd
)");
  ASSERT_EQ(scene_notes(b).size(), 3u);
  EXPECT_EQ(scene_notes(b)[0].message, "Attribute \"visibility\" \"camera\" has no effect in darc: ignored");
  EXPECT_EQ(scene_notes(b)[1].message, "Attribute \"visibility\" \"diffuse\" has no effect in darc: ignored");
  EXPECT_EQ(scene_notes(b)[2].message, "Attribute \"render\" \"visibility\" has no effect in darc: ignored");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].materials[0].transmission, Transmission::Opaque);
}

// Materials are interned per attribute state, and the transmission is part of that state.
TEST(SceneBuilderShadows, TransmissionSeparatesMaterials) {
  Built b = build(R"(WorldBegin
Sphere 1 -1 1 360
AttributeBegin
  Attribute "visibility" "string transmission" ["transparent"]
  Sphere 1 -1 1 360
  Sphere 1 -1 1 360
AttributeEnd
Sphere 1 -1 1 360
ObjectBegin "shadowless"
  Attribute "render" "casts_shadows" "none"
  Sphere 1 -1 1 360
ObjectEnd
ObjectInstance "shadowless"
Sphere 1 -1 1 360
WorldEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  ASSERT_EQ(s.surfaces.spheres.size(), 6u);
  ASSERT_EQ(s.materials.size(), 2u);
  const std::vector<uint32_t>& m = s.surfaces.sphere_material;
  EXPECT_NE(m[0], m[1]) << "differing only in transmission";
  EXPECT_EQ(m[1], m[2]) << "the same state shares one material";
  EXPECT_EQ(m[3], m[0]) << "AttributeEnd restores the transmission";
  EXPECT_EQ(m[4], m[1]) << "an instance's recorded attribute";
  EXPECT_EQ(m[5], m[0]) << "the instance's attributes end with it";
  EXPECT_EQ(s.materials[m[0]].transmission, Transmission::Os);
  EXPECT_EQ(s.materials[m[1]].transmission, Transmission::Transparent);
}

TEST(SceneBuilderTraceDepth, DefaultIsTen) {
  Built b = build("WorldBegin WorldEnd");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].output.trace_max_depth, 10);
}

TEST(SceneBuilderTraceDepth, OptionSetsItAndIsFrameScoped) {
  Built b = build(R"(Option "trace" "int maxdepth" [3]
FrameBegin 1
Option "trace" "maxdepth" 0
WorldBegin WorldEnd
FrameEnd
FrameBegin 2
WorldBegin WorldEnd
FrameEnd
)");
  ASSERT_EQ(b.scenes.size(), 2u);
  EXPECT_EQ(b.scenes[0].output.trace_max_depth, 0);
  EXPECT_EQ(b.scenes[1].output.trace_max_depth, 3) << "FrameEnd restores the option";
  EXPECT_TRUE(scene_notes(b).empty());
}

TEST(SceneBuilderTraceDepth, NegativeOrFractionalIsAnError) {
  Built b = build(R"(Option "trace" "int maxdepth" [-1]
Option "trace" "maxdepth" [2.5]
Option "trace" "maxdepth" [1 2]
WorldBegin WorldEnd
)");
  std::vector<Diagnostic> e = reported(b, Severity::Error, "Option \"trace\" \"maxdepth\" must be");
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].message, "Option \"trace\" \"maxdepth\" must be an integer >= 0, found -1");
  EXPECT_EQ(e[0].request, "Option");
  EXPECT_EQ(e[0].loc.line, 1);
  EXPECT_EQ(e[1].loc.line, 2);
  EXPECT_EQ(e[2].message, "Option \"trace\" \"maxdepth\" must be one integer");
  ASSERT_EQ(b.scenes.size(), 1u) << "errors before WorldBegin are the frame's, and it is built";
  EXPECT_EQ(b.frame_errors[0].count, 3);
  EXPECT_EQ(b.scenes[0].output.trace_max_depth, 10) << "a rejected value changes nothing";
}

TEST(SceneBuilderTraceDepth, OtherTraceOptionsWarnOncePerNameAndTheWorldBlockIgnoresIt) {
  Built b = build(R"(Option "trace" "float bias" [0.01] "int maxdepth" [4]
Option "trace" "float bias" [0.02] "string samplemode" ["fixed"]
WorldBegin
Option "trace" "maxdepth" 7
WorldEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].output.trace_max_depth, 4);
  ASSERT_EQ(scene_notes(b).size(), 3u);
  EXPECT_EQ(scene_notes(b)[0].message, "Option \"trace\" \"bias\" has no effect in darc: ignored");
  EXPECT_EQ(scene_notes(b)[1].message, "Option \"trace\" \"samplemode\" has no effect in darc: ignored");
  EXPECT_EQ(scene_notes(b)[2].message, "options cannot change inside WorldBegin/WorldEnd: ignored");
  EXPECT_EQ(scene_notes(b)[2].loc.line, 4);
}

}  // namespace
}  // namespace darc
