// SceneBuilder's Points: P, width / constantwidth / Cs / Os by their classes, the default width,
// clamping warnings and located errors for bad counts.
#include <gtest/gtest.h>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

Built build_world(const std::string& body) { return build("WorldBegin\n" + body + "\nWorldEnd\n"); }

std::string first_error(const Built& b) {
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error) return d.str();
  return "";
}

TEST(SceneBuilderPoints, RadiiAreHalfTheWidthsInWorldSpace) {
  Built b = build_world(R"(Scale 2 2 2
Points "P" [0 0 0  1 0 0] "width" [0.5 0.25])");
  ASSERT_EQ(b.scenes.size(), 1u);
  const PointSet& p = b.scenes[0].points;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_FLOAT_EQ(p.radius[0], 0.5f);
  EXPECT_FLOAT_EQ(p.radius[1], 0.25f);
  EXPECT_EQ(p.center[1], (Vec3f{2, 0, 0}));
}

TEST(SceneBuilderPoints, ConstantWidthAndTheDefaultWidthOfOne) {
  Built b = build_world(R"(Points "P" [0 0 0  1 0 0] "constantwidth" 0.1
Points "P" [0 0 1])");
  const PointSet& p = b.scenes.at(0).points;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_FLOAT_EQ(p.radius[0], 0.05f);
  EXPECT_FLOAT_EQ(p.radius[1], 0.05f);
  EXPECT_FLOAT_EQ(p.radius[2], 0.5f) << "RI: Points are 1 wide by default";
}

TEST(SceneBuilderPoints, ColourAndOpacityPerPointOrShared) {
  Built b = build_world(R"(Color 0.2 0.3 0.4
Points "P" [0 0 0  1 0 0] "Cs" [1 0 0  0 1 0] "constant color Os" [0.5 0.5 0.5]
Points "P" [0 0 1])");
  const PointSet& p = b.scenes.at(0).points;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.color(0), (Vec3f{1, 0, 0}));
  EXPECT_EQ(p.color(1), (Vec3f{0, 1, 0}));
  EXPECT_EQ(p.opacity(1), (Vec3f{0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(p.color(2), (Vec3f{0.2f, 0.3f, 0.4f})) << "the attribute colour without Cs";
  EXPECT_EQ(p.opacity(2), (Vec3f{1, 1, 1}));
  EXPECT_EQ(b.scenes[0].primitive_count(), 3u);
}

TEST(SceneBuilderPoints, NegativeWidthsAndOpacitiesOutOfRangeAreClampedWithAWarning) {
  Built b = build_world(R"(Points "P" [0 0 0  1 0 0  2 0 0] "width" [-1 0.5 -0.5] "Os" [2 1 1  1 1 1  1 -1 1])");
  const PointSet& p = b.scenes.at(0).points;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.radius[0], 0.0f);
  EXPECT_EQ(p.radius[2], 0.0f);
  EXPECT_EQ(p.opacity(0), (Vec3f{1, 1, 1}));
  EXPECT_EQ(p.opacity(2), (Vec3f{1, 0, 1}));
  std::vector<std::string> warnings;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Warning) warnings.push_back(d.str());
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("\"width\" (varying) value 0 is -1, negative: clamped to 0 (2 numbers clamped)"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(
      warnings[1].find("\"Os\" (varying) value 0 component 0 is 2, outside [0, 1]: clamped to 1 (2 numbers clamped)"),
      std::string::npos)
      << warnings[1];
}

TEST(SceneBuilderPoints, BadRequestsAreLocatedErrorsAndSkipped) {
  struct Case {
    const char* rib;
    const char* error;
  };
  const Case cases[] = {
      {R"(Points "width" [1])", "test.rib:2:1: error: Points: Points needs \"P\""},
      {R"(Points "P" [0 0 0  1 0 0] "width" [1 2 3])",
       "test.rib:2:1: error: Points: \"width\" (varying) needs 2 numbers for 2 values, found 3"},
      {R"(Points "P" [0 0 0  1 0 0] "Cs" [1 0 0])",
       "test.rib:2:1: error: Points: \"Cs\" (varying) needs 6 numbers for 2 values, found 3"},
      {R"(Points "P" [0 0 0  1 0 0] "uniform float width" [1 2])",
       "test.rib:2:1: error: Points: \"width\" (uniform) needs 1 numbers for 1 value, found 2"},
      {R"(Points "P" [0 0 0 1])", "test.rib:2:8: error: Points: \"P\": point values must come in groups of 3, found 4"},
      {R"(Points "P" [0 0 1e39])", "test.rib:2:17: error: Points: number 1e39 is out of range"},
      {R"(Points "P" [0 0 0] "facevarying float width" [1])",
       "test.rib:2:1: error: Points: \"width\" is facevarying: Points has no faces"},
  };
  for (const Case& c : cases) {
    Built b = build_world(c.rib);
    EXPECT_EQ(first_error(b).rfind(c.error, 0), 0u) << c.rib << "\n" << first_error(b);
    ASSERT_EQ(b.scenes.size(), 1u);
    EXPECT_EQ(b.scenes[0].points.size(), 0u) << "the request is skipped whole";
  }
}

TEST(SceneBuilderPoints, PointsBeyondTheFloatRangeInWorldSpaceAreDroppedWithAWarning) {
  Built b = build_world(R"(Scale 1e30 1e30 1e30
Points "P" [0 0 0  1e10 0 0] "constantwidth" 1e-30)");
  const PointSet& p = b.scenes.at(0).points;
  ASSERT_EQ(p.size(), 1u);
  bool warned = false;
  for (const Diagnostic& d : b.diagnostics)
    warned |= d.str().find("1 point lies beyond the float range in world space: dropped") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(SceneBuilderPoints, ObjectInstancesReplayPoints) {
  Built b = build_world(R"(ObjectBegin "p" Points "P" [0 0 0] "constantwidth" 0.2 ObjectEnd
ObjectInstance "p"
Translate 1 0 0
ObjectInstance "p")");
  const PointSet& p = b.scenes.at(0).points;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p.center[1], (Vec3f{1, 0, 0}));
}

}  // namespace
}  // namespace darc
