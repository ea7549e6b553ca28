// SceneBuilder and the RIB conventions for ray tracing: which lights cast shadows ("shadowname",
// Attribute "light" "shadows").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/scenes_from_rib.h"

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
  EXPECT_TRUE(b.diagnostics.empty()) << "a predeclared parameter, and no shadow-map warning";
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
  EXPECT_EQ(b.diagnostics.size(), 1u);
}

TEST(SceneBuilderShadows, EmptyOrMissingShadownameCastsNone) {
  Built b =
      build("WorldBegin\nLightSource \"spotlight\" 1 \"shadowname\" [\"\"]\nLightSource \"pointlight\" 2\nWorldEnd\n");
  EXPECT_EQ(shadows(b), (std::vector<bool>{false, false}));
  EXPECT_TRUE(b.diagnostics.empty());
}

TEST(SceneBuilderShadows, ShadownameMustBeAString) {
  Built b = build("WorldBegin\nLightSource \"spotlight\" 1 \"float shadowname\" [1]\nWorldEnd\n");
  EXPECT_EQ(b.failed, std::vector<int>{1});
  const std::vector<Diagnostic> e = reported(b, Severity::Error, "\"shadowname\" must be one string");
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
  EXPECT_TRUE(b.diagnostics.empty());
}

TEST(SceneBuilderShadows, LightShadowsValueOtherThanOnOrOffIsAnError) {
  Built b = build(R"(WorldBegin
Attribute "light" "string shadows" ["yes"]
Attribute "light" "shadows" [1]
LightSource "pointlight" 1
WorldEnd
)");
  EXPECT_EQ(b.failed, std::vector<int>{1});
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
  ASSERT_EQ(b.diagnostics.size(), 2u);
  EXPECT_EQ(b.diagnostics[0].message, "Attribute \"light\" \"nsamples\" has no effect in darc: ignored");
  EXPECT_EQ(b.diagnostics[1].message, "Attribute \"identifier\" has no effect in darc: ignored")
      << "categories darc does not read at all still warn once per category";
}

}  // namespace
}  // namespace darc
