// SceneBuilder's motion blocks: a moving transform and a deformation block give Curves keys at
// shutter open and close (and the times between), a turning transform gets enough keys for its
// arc, nested transforms compose over time, and a closed shutter builds the shape at its open time.
// Polygons and tessellated surfaces move as triangles; a moving camera moves the world the other
// way, and a camera block whose samples agree moves nothing.
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

bool has_warning(const Built& b, const std::string& text) {
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Warning && d.message.find(text) != std::string::npos) return true;
  return false;
}

TEST(SceneBuilderMotion, APolygonDeformationBlockMovesItsTriangles) {
  Built b = build_world("Shutter 0 1",
                        "MotionBegin [0 1]\n"
                        "PointsPolygons [4] [0 1 2 3] \"P\" [0 0 5  1 0 5  1 1 5  0 1 5]\n"
                        "PointsPolygons [4] [0 1 2 3] \"P\" [0 0 5  3 0 5  3 1 5  0 1 5]\n"
                        "MotionEnd\n");
  const SurfaceSet& s = b.scenes.at(0).surfaces;
  EXPECT_TRUE(s.polygons.empty()) << "a moving face is a fan of moving triangles";
  ASSERT_EQ(s.triangles.size(), 2u);
  ASSERT_TRUE(s.has_motion());
  EXPECT_TRUE(s.triangles.moving(0));
  EXPECT_FLOAT_EQ(s.triangles.corner(0, 1, 0.0f).x, 1.0f);
  EXPECT_FLOAT_EQ(s.triangles.corner(0, 1, 0.5f).x, 2.0f);
  EXPECT_FLOAT_EQ(s.triangles.corner(0, 1, 1.0f).x, 3.0f);
  EXPECT_FLOAT_EQ(s.triangles.corner(0, 0, 1.0f).x, 0.0f) << "a corner that stays";
  EXPECT_GE(s.triangles.bounds(0).hi.x, 3.0f) << "the box holds the whole shutter";
  for (const Diagnostic& d : b.diagnostics) ADD_FAILURE() << d.str();
}

TEST(SceneBuilderMotion, APatchUnderAMovingTransformMoves) {
  Built b = build_world("Shutter 0 1", "MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 0 2 0\nMotionEnd\n"
                                       "Patch \"bilinear\" \"P\" [0 0 5  1 0 5  0 1 5  1 1 5]\n");
  const SurfaceSet& s = b.scenes.at(0).surfaces;
  ASSERT_GT(s.triangles.size(), 0u);
  ASSERT_TRUE(s.triangles.moving(0));
  for (uint32_t t = 0; t < s.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_FLOAT_EQ(s.triangles.corner(t, k, 1.0f).y, s.triangles.corner(t, k, 0.0f).y + 2.0f);
  // A ray at shutter close meets it where it has gone.
  Ray ray;
  ray.o = {0.5f, 2.5f, 0};
  ray.d = {0, 0, 1};
  ray.time = 1.0f;
  bool hit = false;
  for (uint32_t i = 0; i < s.size(); ++i) {
    SurfaceHit h;
    hit = hit || s.intersect(i, ray, h);
  }
  EXPECT_TRUE(hit);
  ray.time = 0.0f;
  hit = false;
  for (uint32_t i = 0; i < s.size(); ++i) {
    SurfaceHit h;
    hit = hit || s.intersect(i, ray, h);
  }
  EXPECT_FALSE(hit) << "not there at shutter open";
}

TEST(SceneBuilderMotion, AMovingCameraMovesTheWorldTheOtherWay) {
  Built b = build("Shutter 0 1\nMotionBegin [0 1]\nTranslate 0 0 0\nTranslate -3 0 0\nMotionEnd\nWorldBegin\n" +
                  std::string(kStrand) + "Sphere 1 -1 1 360\nWorldEnd\n");
  const Scene& scene = b.scenes.at(0);
  ASSERT_TRUE(scene.curves.moving(0));
  EXPECT_FLOAT_EQ(point_at(scene.curves, 0, 0.0f, 0).x, 4.0f) << "the camera renders from where it is at open";
  EXPECT_FLOAT_EQ(point_at(scene.curves, 0, 1.0f, 0).x, 1.0f);
  EXPECT_TRUE(scene.surfaces.spheres.empty()) << "a moving sphere is a moving triangle mesh";
  ASSERT_GT(scene.surfaces.triangles.size(), 0u);
  EXPECT_TRUE(scene.surfaces.triangles.moving(0));
  EXPECT_FALSE(has_warning(b, "motion blur"));
}

TEST(SceneBuilderMotion, ACameraBlockWhoseSamplesAgreeMovesNothing) {
  Built b = build("Shutter 0 1\nMotionBegin [0 1]\nTranslate 1 0 0\nTranslate 1 0 0\nMotionEnd\nWorldBegin\n" +
                  std::string(kStrand) + "Polygon \"P\" [0 0 5  1 0 5  1 1 5]\nWorldEnd\n");
  const Scene& scene = b.scenes.at(0);
  EXPECT_FALSE(scene.has_motion());
  EXPECT_EQ(scene.surfaces.polygons.size(), 1u);
  EXPECT_FLOAT_EQ(scene.camera.world_to_camera.transform_point(Vec3d{0, 0, 0}).x, 1.0f);
}

TEST(SceneBuilderMotion, UnderAMovingCameraTheWorldsSpacesMoveAndCameraSpaceStays) {
  Built b = build("Shutter 0 1\nMotionBegin [0 1]\nTranslate 0 0 0\nTranslate -3 0 0\nMotionEnd\nWorldBegin\n"
                  "AttributeBegin\nCoordSysTransform \"world\"\n" +
                  std::string(kStrand) + "AttributeEnd\nAttributeBegin\nCoordSysTransform \"camera\"\n" + kStrand +
                  "AttributeEnd\nWorldEnd\n");
  const CurveSet& cs = b.scenes.at(0).curves;
  ASSERT_EQ(cs.size(), 2u);
  ASSERT_TRUE(cs.moving(0));
  EXPECT_FLOAT_EQ(point_at(cs, 0, 1.0f, 0).x, 1.0f) << "placed in the world: moves with it";
  EXPECT_FALSE(cs.moving(1)) << "placed in camera space: stays where the image's camera sees it";
}

TEST(SceneBuilderMotion, ADeformingSubdivisionMeshAndPatchMoveTheirTessellation) {
  Built b = build_world("Shutter 0 1",
                        "MotionBegin [0 1]\n"
                        "SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [\"interpolateboundary\"] [0 0] [] [] \"P\" [0 0 5  1 0 5  1 1 5  0 1 5]\n"
                        "SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [\"interpolateboundary\"] [0 0] [] [] \"P\" [0 0 5  1 0 5  1 1 7  0 1 7]\n"
                        "MotionEnd\n"
                        "MotionBegin [0 1]\n"
                        "Patch \"bilinear\" \"P\" [4 0 5  5 0 5  4 1 5  5 1 5]\n"
                        "Patch \"bilinear\" \"P\" [4 0 5  5 0 5  4 3 5  5 3 5]\n"
                        "MotionEnd\n");
  const TriangleStore& t = b.scenes.at(0).surfaces.triangles;
  ASSERT_GT(t.size(), 2u);
  float subdivision_rise = 0, patch_reach = 0;
  for (uint32_t i = 0; i < t.size(); ++i) {
    ASSERT_TRUE(t.moving(i)) << i;
    for (int k = 0; k < 3; ++k) {
      const Vec3f open = t.corner(i, k, 0.0f), close = t.corner(i, k, 1.0f);
      if (open.x < 2) subdivision_rise = std::max(subdivision_rise, close.z - open.z);
      if (open.x > 3) patch_reach = std::max(patch_reach, close.y);
      EXPECT_FLOAT_EQ(open.x, close.x);
    }
  }
  EXPECT_GT(subdivision_rise, 1.0f) << "the limit surface's far edge rises towards z = 7";
  EXPECT_FLOAT_EQ(patch_reach, 3.0f);
  for (const Diagnostic& d : b.diagnostics) ADD_FAILURE() << d.str();
}

TEST(SceneBuilderMotion, PointsMoveWithTheirSamplesAndWithAMovingTransform) {
  Built b = build_world("Shutter 0 1",
                        "MotionBegin [0 1]\nPoints \"P\" [0 0 5  1 0 5] \"width\" [0.1 0.1]\n"
                        "Points \"P\" [0 2 5  1 0 5] \"width\" [0.2 0.1]\nMotionEnd\n"
                        "MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 3 0 0\nMotionEnd\n"
                        "Points \"P\" [0 0 5] \"constantwidth\" [1]\n");
  const PointSet& p = b.scenes.at(0).points;
  ASSERT_EQ(p.size(), 3u);
  ASSERT_TRUE(p.moving(0));
  EXPECT_FALSE(p.moving(1)) << "a point whose samples agree stays";
  EXPECT_FLOAT_EQ(p.center_at(0, 0.5f).y, 1.0f);
  EXPECT_FLOAT_EQ(p.radius_at(0, 1.0f), 0.1f);
  EXPECT_FLOAT_EQ(p.radius_at(0, 0.0f), 0.05f);
  EXPECT_GE(p.bounds(0).hi.y, 2.1f) << "the box holds the whole shutter";
  ASSERT_TRUE(p.moving(2));
  EXPECT_FLOAT_EQ(p.center_at(2, 1.0f).x, 3.0f);
  EXPECT_FLOAT_EQ(p.center[2].x, 0.0f) << "the point at shutter open";
  for (const Diagnostic& d : b.diagnostics) ADD_FAILURE() << d.str();
}

}  // namespace
}  // namespace darc
