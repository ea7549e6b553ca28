// SceneBuilder and AreaLightSource: area lights light nothing in darc (their geometry is drawn
// emissive), but their handles are lights' handles all the same, for Illuminate.
#include <gtest/gtest.h>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

std::vector<Diagnostic> errors(const Built& b) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error) out.push_back(d);
  return out;
}

TEST(SceneBuilderAreaLights, IlluminateKnowsAnAreaLightHandle) {
  Built b = build(R"RIB(WorldBegin
AttributeBegin
  AreaLightSource "arealight" 1 "float intensity" [2]
  Illuminate 1 1
  Sphere 1 -1 1 360
AttributeEnd
Illuminate 1 0
AttributeBegin
  AreaLightSource "arealight" "panel"
AttributeEnd
Illuminate "panel" 1
WorldEnd
)RIB");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(errors(b).empty()) << errors(b)[0].str();
  EXPECT_EQ(b.frame_errors[0].count, 0);
  ASSERT_EQ(b.scenes[0].surfaces.spheres.size(), 1u);
  EXPECT_EQ(b.scenes[0].materials[b.scenes[0].surfaces.sphere_material[0]].emissive_area_light, "arealight")
      << "the fallback stays: the geometry is drawn emissive";
}

TEST(SceneBuilderAreaLights, AHandleNamesTheLatestLightDeclaredWithIt) {
  Built b = build(R"RIB(WorldBegin
LightSource "pointlight" 1
AreaLightSource "arealight" 1
Illuminate 1 0
Sphere 1 -1 1 360
WorldEnd
)RIB");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(errors(b).empty());
  const Scene& s = b.scenes[0];
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[0]].lights.size(), 1u)
      << "Illuminate 1 0 switched the area light, not the point light it replaced";
}

TEST(SceneBuilderAreaLights, AnUnknownHandleIsStillAnError) {
  Built b = build("WorldBegin\nAreaLightSource \"arealight\" 1\nIlluminate 2 1\nWorldEnd\n");
  ASSERT_EQ(errors(b).size(), 1u);
  EXPECT_EQ(errors(b)[0].message, "unknown light handle \"2\"");
}

}  // namespace
}  // namespace darc
