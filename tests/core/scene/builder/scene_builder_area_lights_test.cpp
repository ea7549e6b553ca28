// SceneBuilder and AreaLightSource: an area light is a light of the scene (on, in the current
// light list, its handle good for Illuminate) whose shape is the geometry of its attribute block,
// drawn emissive and transparent to shadow rays (shading/geometry_light.h makes the light).
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
  const Scene& s = b.scenes[0];
  const Material& m = s.materials[s.surfaces.sphere_material[0]];
  EXPECT_EQ(m.emissive_area_light, "arealight") << "the geometry is drawn emissive";
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_TRUE(s.lights[0].geometry);
  EXPECT_EQ(m.area_light, 0) << "the sphere is the first light's shape";
  EXPECT_EQ(m.transmission, Transmission::Transparent) << "an emitter does not shadow its own light";
}

TEST(SceneBuilderAreaLights, TheLightIsOnForWhatFollowsInItsBlockAndAfterIlluminate) {
  Built b = build(R"RIB(WorldBegin
AttributeBegin
  AreaLightSource "arealight" "lamp" "float intensity" [2]
  Polygon "P" [0 1 0  1 1 0  1 1 1]
  AttributeBegin
    Surface "matte"
    Sphere 1 -1 1 360
  AttributeEnd
AttributeEnd
Sphere 2 -1 1 360
Illuminate "lamp" 1
Sphere 3 -1 1 360
WorldEnd
)RIB");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  ASSERT_EQ(s.lights.size(), 1u);
  auto lights_of = [&](int k) { return s.materials[s.surfaces.sphere_material[size_t(k)]].lights; };
  EXPECT_EQ(lights_of(0), (std::vector<uint32_t>{0}));
  EXPECT_TRUE(lights_of(1).empty()) << "off after its block, as any light in the attribute state";
  EXPECT_EQ(lights_of(2), (std::vector<uint32_t>{0}));
  // Every primitive until the AttributeEnd of the light's block is part of its shape, nested
  // blocks and their Surface calls included (RI Spec 3.2, RiAreaLightSource).
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[0]].area_light, 0);
  EXPECT_EQ(s.materials[s.surfaces.sphere_material[1]].area_light, -1);
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
