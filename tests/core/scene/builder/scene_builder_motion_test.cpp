// SceneBuilder's motion blocks: a moving transform and a deformation block give Curves keys at
// shutter open and close (and the times between), a turning transform gets enough keys for its
// arc, nested transforms compose over time, and a closed shutter builds the shape at its open time.
#include "support/scenes_from_rib.h"

#include <gtest/gtest.h>

#include <cmath>

namespace darc {
namespace {

using test::Built;
using test::build;

const char* kStrand = "Curves \"linear\" [2] \"nonperiodic\" \"P\" [4 0 5  6 0 5] \"constantwidth\" [0.5]\n";

Built build_world(const std::string& shutter, const std::string& world) {
  return build(shutter + "\nWorldBegin\n" + world + "WorldEnd\n");
}

Vec3f point_at(const CurveSet& cs, size_t segment, float time, int k) {
  Vec3f at[4];
  return cs.control_points_at(segment, time, at)[k];
}

TEST(SceneBuilderMotion, ATranslateBlockMovesCurvesBetweenShutterOpenAndClose) {
  // Times beyond the shutter: the keys are the shape at open (0.25) and close (0.75).
  Built b = build_world("Shutter 0.25 0.75", std::string("MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 4 0 0\nMotionEnd\n") + kStrand);
  ASSERT_EQ(b.scenes.size(), 1u);
  const CurveSet& cs = b.scenes[0].curves;
  ASSERT_TRUE(cs.moving(0));
  EXPECT_EQ(cs.motions[cs.motion[0]].keys, 2u);
  EXPECT_FLOAT_EQ(cs.cp[0].x, 5.0f) << "cp holds the shape at shutter open";
  EXPECT_FLOAT_EQ(point_at(cs, 0, 1.0f, 0).x, 7.0f);
  EXPECT_FLOAT_EQ(point_at(cs, 0, 0.5f, 0).x, 6.0f);
  // The bounds hold the whole motion.
  EXPECT_LE(cs.segment_bounds(0).lo.x, 5.0f - 0.25f);
  EXPECT_GE(cs.segment_bounds(0).hi.x, 9.0f + 0.25f);
}

TEST(SceneBuilderMotion, ADeformationBlockKeepsItsMiddleSample) {
  Built b = build_world("Shutter 0 1",
                        "MotionBegin [0 0.5 1]\n"
                        "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 5  1 0 5]\n"
                        "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 3 5  1 3 5]\n"
                        "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 5  1 0 5]\nMotionEnd\n");
  const CurveSet& cs = b.scenes.at(0).curves;
  ASSERT_TRUE(cs.moving(0));
  EXPECT_EQ(cs.motions[cs.motion[0]].keys, 3u);
  EXPECT_FLOAT_EQ(point_at(cs, 0, 0.5f, 0).y, 3.0f);
  EXPECT_FLOAT_EQ(point_at(cs, 0, 0.25f, 0).y, 1.5f);
  EXPECT_FLOAT_EQ(point_at(cs, 0, 1.0f, 0).y, 0.0f);
}

TEST(SceneBuilderMotion, ATurningTransformGetsKeysAlongItsArc) {
  Built b = build_world("Shutter 0 1", std::string("MotionBegin [0 1]\nRotate 0 0 0 1\nRotate 90 0 0 1\nMotionEnd\n") + kStrand);
  const CurveSet& cs = b.scenes.at(0).curves;
  ASSERT_TRUE(cs.moving(0));
  EXPECT_GE(cs.motions[cs.motion[0]].keys, 9u) << "a quarter turn needs keys every few degrees";
  // Anywhere in the shutter the strand's outer point stays near radius 6 (a chord would cut in to 4.2).
  for (float t : {0.1f, 0.3f, 0.5f, 0.77f}) {
    const Vec3f p = point_at(cs, 0, t, 3);
    EXPECT_NEAR(std::hypot(p.x, p.y), 6.0f, 6.0f * 4e-3f) << t;
  }
}

TEST(SceneBuilderMotion, NestedMovingTransformsCompose) {
  Built b = build_world("Shutter 0 1",
                        std::string("MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 0 2 0\nMotionEnd\n"
                                    "AttributeBegin\nMotionBegin [0 1]\nTranslate 0 0 0\nTranslate 10 0 0\nMotionEnd\n") +
                            kStrand + "AttributeEnd\n" + kStrand);
  const CurveSet& cs = b.scenes.at(0).curves;
  ASSERT_EQ(cs.size(), 2u);
  EXPECT_FLOAT_EQ(point_at(cs, 0, 1.0f, 0).x, 14.0f);
  EXPECT_FLOAT_EQ(point_at(cs, 0, 1.0f, 0).y, 2.0f);
  EXPECT_FLOAT_EQ(point_at(cs, 1, 1.0f, 0).x, 4.0f) << "AttributeEnd restores the outer motion";
  EXPECT_FLOAT_EQ(point_at(cs, 1, 1.0f, 0).y, 2.0f);
}

TEST(SceneBuilderMotion, AClosedShutterBuildsTheShapeAtItsOpenTime) {
  Built b = build_world("Shutter 0.5 0.5", std::string("MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 4 0 0\nMotionEnd\n") + kStrand);
  const CurveSet& cs = b.scenes.at(0).curves;
  EXPECT_FALSE(cs.has_motion());
  EXPECT_FLOAT_EQ(cs.cp[0].x, 6.0f);
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error) ADD_FAILURE() << d.str();
}

TEST(SceneBuilderMotion, AnObjectInstanceReplaysItsMotionBlock) {
  Built b = build_world("Shutter 0 1", std::string("ObjectBegin \"tuft\"\nMotionBegin [0 1]\nTranslate 0 0 0\nTranslate 0 1 0\nMotionEnd\n") +
                                           kStrand + "ObjectEnd\nObjectInstance \"tuft\"\n");
  const CurveSet& cs = b.scenes.at(0).curves;
  ASSERT_TRUE(cs.moving(0));
  EXPECT_FLOAT_EQ(point_at(cs, 0, 1.0f, 0).y, 1.0f);
}

}  // namespace
}  // namespace darc
