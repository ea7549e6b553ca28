// SceneBuilder: the RI graphics state, frames, instancing and the scenes it hands over.
#include "core/scene/builder/scene_builder.h"
#include "parser/rib_parser.h"
#include "support/scenes_from_rib.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace darc {
namespace {

using test::Built;
using test::build;

std::set<uint32_t> strands(const CurveSet& cs) { return {cs.strand_id.begin(), cs.strand_id.end()}; }

TEST(SceneBuilder, SharedBezierGrassHasOneHundredStrands) {
  std::filesystem::path f = std::filesystem::path(DARC_SHARED_RIBS_DIR) / "aqsis" / "Curves_bezier.rib";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << "shared RIBs not found: " << f;
  Built out;
  Diagnostics diag([&](const Diagnostic& d) { out.diagnostics.push_back(d); });
  SceneBuilder::Callbacks cb;
  cb.frame_ready = [&](Scene&& s) { out.scenes.push_back(std::move(s)); };
  SceneBuilder builder(diag, cb);
  RibParser parser(builder, diag);
  ASSERT_TRUE(parser.parse_file(f.string()));
  ASSERT_EQ(out.scenes.size(), 1u);
  const CurveSet& cs = out.scenes[0].curves;
  EXPECT_EQ(strands(cs).size(), 100u);
  EXPECT_EQ(cs.size(), 100u) << "one cubic Bézier segment per 4-vertex curve";
  // Varying width 0.3 -> 0 becomes the elevated linear Bézier (0.3, 0.2, 0.1, 0).
  EXPECT_NEAR(cs.width[0], 0.3f, 1e-6f);
  EXPECT_NEAR(cs.width[3], 0.0f, 1e-6f);
  EXPECT_EQ(out.scenes[0].output.display_name, "bezier.tif");
  EXPECT_EQ(out.scenes[0].lights.size(), 1u);
}

TEST(SceneBuilder, WorldBlocksBecomeFramesAndOptionsAreFrameScoped) {
  Built b = build(R"(Format 100 50 1
FrameBegin 7
Format 20 10 1
Display "a.exr" "file" "rgba"
WorldBegin Sphere 1 -1 1 360 WorldEnd
FrameEnd
FrameBegin 8
WorldBegin Sphere 1 -1 1 360 WorldEnd
FrameEnd)");
  ASSERT_EQ(b.scenes.size(), 2u);
  EXPECT_EQ(b.scenes[0].output.frame_number, 7);
  EXPECT_EQ(b.scenes[0].output.xres, 20);
  EXPECT_EQ(b.scenes[1].output.xres, 100) << "Format inside frame 7 is restored at FrameEnd";
  EXPECT_EQ(b.scenes[1].output.display_name, "ri.tif");
}

TEST(SceneBuilder, FrameSelectionSkipsBuilding) {
  Built b = build("FrameBegin 1 WorldBegin WorldEnd FrameEnd FrameBegin 2 WorldBegin WorldEnd FrameEnd",
                  [](int f) { return f == 2; });
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].output.frame_number, 2);
}

TEST(SceneBuilder, ErrorsSkipTheirRequestAndCountOnlyForTheirFrame) {
  Built b = build(R"(FrameBegin 1 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd
FrameBegin 2 WorldBegin Curves "cubic" [5] "nonperiodic" "P" [0 0 0 1 1 1 2 2 2 3 3 3 4 4 4] Sphere 1 -1 1 360 WorldEnd FrameEnd
FrameBegin 3 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd)");
  ASSERT_EQ(b.scenes.size(), 3u) << "a frame with an error is still built, without the bad request";
  EXPECT_TRUE(b.failed.empty());
  EXPECT_EQ(b.scenes[1].output.frame_number, 2);
  EXPECT_EQ(b.scenes[1].curves.size(), 0u);
  EXPECT_EQ(b.scenes[1].surfaces.spheres.size(), 1u) << "the requests after the bad one are built";
  ASSERT_EQ(b.frame_errors.size(), 3u);
  EXPECT_EQ(b.frame_errors[0].count, 0);
  EXPECT_EQ(b.frame_errors[1].count, 1);
  EXPECT_EQ(b.frame_errors[1].first.rfind("test.rib:2:", 0), 0u) << b.frame_errors[1].first;
  EXPECT_EQ(b.frame_errors[2].count, 0) << "frame 2's error is not frame 3's";
  EXPECT_EQ(b.frame_errors[2].first, "");
  bool located = false;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error && d.loc.line == 2) located = true;
  EXPECT_TRUE(located) << "the Bézier count error points at line 2";
}

TEST(SceneBuilder, ObjectInstancesReplayTheirGeometry) {
  Built b = build(R"(WorldBegin
ObjectBegin "blade" Curves "linear" [2] "nonperiodic" "P" [0 0 0 0 1 0] "constantwidth" 0.1 ObjectEnd
Translate 1 0 0 ObjectInstance "blade"
Translate 1 0 0 ObjectInstance "blade"
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const CurveSet& cs = b.scenes[0].curves;
  ASSERT_EQ(cs.size(), 2u);
  EXPECT_NEAR(cs.cp[0].x, 1.0f, 1e-6f);
  EXPECT_NEAR(cs.cp[4].x, 2.0f, 1e-6f);
  EXPECT_EQ(strands(cs).size(), 2u) << "each instance is its own strand";
}

TEST(SceneBuilder, MotionBlocksUseTheFirstSample) {
  Built b = build(R"(WorldBegin
MotionBegin [0 1] Translate 1 0 0 Translate 5 0 0 MotionEnd
Sphere 1 -1 1 360
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  ASSERT_EQ(b.scenes[0].surfaces.spheres.size(), 1u);
  EXPECT_NEAR(b.scenes[0].surfaces.spheres[0].bounds().center().x, 1.0f, 1e-4f);
}

TEST(SceneBuilder, LightsFollowIlluminateAndAttributeScopes) {
  Built b = build(R"(LightSource "distantlight" "key"
WorldBegin
LightSource "pointlight" 2 "from" [0 5 0]
AttributeBegin
  LightSource "ambientlight" 3
  Illuminate "key" 0
  Sphere 1 -1 1 360
AttributeEnd
Sphere 1 -1 1 360
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].shader, "distantlight") << "a light before WorldBegin becomes a world light";
  auto on = [&](uint32_t sphere) {
    std::set<std::string> names;
    for (uint32_t l : s.materials[s.surfaces.sphere_material[sphere]].lights) names.insert(s.lights[l].shader);
    return names;
  };
  EXPECT_EQ(on(0), (std::set<std::string>{"pointlight", "ambientlight"}));
  EXPECT_EQ(on(1), (std::set<std::string>{"distantlight", "pointlight"})) << "AttributeEnd restores the light set";
}

TEST(SceneBuilder, OrientationAndHandednessDecideNormalFlips) {
  Built b = build(R"(WorldBegin
Sphere 1 -1 1 360
Scale -1 1 1 Sphere 1 -1 1 360
ReverseOrientation Sphere 1 -1 1 360
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  EXPECT_FALSE(s.materials[s.surfaces.sphere_material[0]].flip_normals);
  EXPECT_TRUE(s.materials[s.surfaces.sphere_material[1]].flip_normals) << "a mirror flips the coordinate system";
  EXPECT_FALSE(s.materials[s.surfaces.sphere_material[2]].flip_normals);
}

TEST(SceneBuilder, UnbalancedBlocksAreErrors) {
  // A block left open at WorldEnd is an error, closed there: the frame is built.
  Built b = build("WorldBegin AttributeBegin Sphere 1 -1 1 360 WorldEnd");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.spheres.size(), 1u);
  ASSERT_EQ(b.frame_errors.size(), 1u);
  EXPECT_EQ(b.frame_errors[0].count, 1);
  EXPECT_EQ(b.frame_errors[0].first,
            "test.rib:1:45: error: WorldEnd: AttributeBegin at test.rib:1:12 is still open: closed here");
  // A world block the input never closes is not rendered (RI renders at WorldEnd).
  Built unclosed = build("WorldBegin Sphere 1 -1 1 360");
  EXPECT_TRUE(unclosed.scenes.empty());
  EXPECT_EQ(unclosed.failed, std::vector<int>{1});
  bool error = false;
  for (const Diagnostic& d : unclosed.diagnostics) error |= d.severity == Severity::Error;
  EXPECT_TRUE(error);
  // Closing blocks that were never opened: each is an error, the rest builds.
  Built extra = build("WorldBegin AttributeEnd TransformEnd Sphere 1 -1 1 360 WorldEnd");
  ASSERT_EQ(extra.scenes.size(), 1u);
  EXPECT_EQ(extra.frame_errors[0].count, 2);
}

}  // namespace
}  // namespace darc

namespace darc {
namespace {

// Materials are interned: one per distinct attribute state, however many primitive requests.
TEST(SceneBuilder, OneMaterialPerDistinctAttributeState) {
  const char* strand = "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 0 1 0 0] \"constantwidth\" [0.1]\n";
  std::string rib = "WorldBegin\nSurface \"matte\" \"Kd\" [0.5]\n";
  for (int i = 0; i < 50; ++i) rib += strand;                       // 50 calls, one state
  rib += std::string("AttributeBegin\n") + strand + "AttributeEnd\n";  // same state again
  rib += std::string("Color [1 0 0]\n") + strand + strand;            // a second state
  rib += std::string("Surface \"matte\" \"Kd\" [0.5]\n") + strand;   // a new Surface call: a third
  rib += "Sphere 1 -1 1 360\n";                                       // shares the third
  rib += "WorldEnd\n";
  Built b = build(rib);
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  EXPECT_EQ(s.curves.size(), 54u);
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.curves.attribute_id[0], s.curves.attribute_id[50]);
  EXPECT_NE(s.curves.attribute_id[50], s.curves.attribute_id[51]);
  EXPECT_EQ(s.materials[s.curves.attribute_id[51]].color, (Vec3f{1, 0, 0}));
  EXPECT_EQ(s.surfaces.sphere_material[0], s.curves.attribute_id[53]);
}

}  // namespace
}  // namespace darc
