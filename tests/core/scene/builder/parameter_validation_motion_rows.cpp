// The rows of docs/parameters.md about motion blur: motion blocks, samples that do not agree,
// the shutter and the camera's shutter opening (parameter_validation_test.cpp runs them).
#include <gtest/gtest.h>

#include "core/scene/builder/parameter_validation_rows.h"

namespace darc::test {

std::vector<Row> motion_rows() {
  return {
      {"motion-times", in_world("MotionBegin [1 0]\nSphere 1 -1 1 360\nSphere 2 -2 2 360\nMotionEnd"),
       error(2, "MotionBegin", "times must increase, found [1 0]: the block keeps its first sample"),
       [](const Scene& s) { EXPECT_EQ(s.surfaces.spheres.size(), 1u); }},
      {"motion-count", "Shutter 0 1\n" + in_world("MotionBegin [0 0.5 1]\nTranslate 1 0 0\nTranslate 2 0 0\nMotionEnd\n" + kLine3),
       error(6, "MotionEnd", "the block at " + kRibName + ":3:1 has 3 times but 2 requests: it keeps its first sample"),
       [](const Scene& s) {
         EXPECT_FALSE(s.curves.has_motion());
         EXPECT_FLOAT_EQ(s.curves.cp[0].x, 1.0f) << "the first sample";
       }},
      {"motion-mixed", "Shutter 0 1\n" + in_world("MotionBegin [0 1]\nTranslate 1 0 0\nRotate 90 0 0 1\nMotionEnd\n" + kLine3),
       error(5, "Rotate",
             "a motion block holds one kind of request: Rotate after Translate (block at " + kRibName +
                 ":3:1); the block keeps its first sample"),
       [](const Scene& s) {
         EXPECT_FALSE(s.curves.has_motion());
         EXPECT_FLOAT_EQ(s.curves.cp[0].x, 1.0f) << "the first sample";
       }},
      {"motion-nested", in_world("MotionBegin [0 1]\nMotionBegin [0 1]\nMotionEnd"),
       error(3, "MotionBegin", "MotionBegin inside the motion block opened at " + kRibName + ":2:1"),
       [](const Scene&) {}},
      {"motion-curves-topology",
       "Shutter 0 1\n" + in_world("MotionBegin [0 1]\n" + kLine3 +
                                  "\nCurves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 0  1 0 0]\nMotionEnd"),
       error(5, "Curves",
             "motion sample 2 is not the same curves as the first (type, wrap and vertex counts must agree): the first "
             "sample is built without motion blur"),
       [](const Scene& s) {
         EXPECT_EQ(s.curves.size(), 2u);
         EXPECT_FALSE(s.curves.has_motion());
       }},
      {"motion-polygons-topology",
       "Shutter 0 1\n" + in_world("MotionBegin [0 1]\nPointsPolygons [3] [0 1 2] \"P\" [0 0 0  1 0 0  0 1 0]\n"
                                  "PointsPolygons [3] [0 2 1] \"P\" [0 0 0  1 0 0  0 1 0]\nMotionEnd"),
       error(5, "PointsPolygons",
             "motion sample 2 is not the same mesh as the first (faces, loops and vertex indices must agree): the "
             "first sample is built without motion blur"),
       [](const Scene& s) {
         EXPECT_EQ(s.surfaces.polygons.size(), 1u);
         EXPECT_FALSE(s.has_motion());
       }},
      {"motion-polygons-concave",
       "Shutter 0 1\n" + in_world("MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 1 0 0\nMotionEnd\n"
                                  "Polygon \"P\" [0 0 0  2 0 0  1 0.5 0  2 2 0  0 2 0]"),
       warning(7, "Polygon", "motion blur of polygons with holes or concave faces is not supported: built at shutter open"),
       [](const Scene& s) {
         EXPECT_EQ(s.surfaces.polygons.size(), 1u);
         EXPECT_FALSE(s.has_motion());
       }},
      {"motion-tessellation-differs",
       "Shutter 0 1\n" + in_world("MotionBegin [0 1]\nSubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] "
                                  "[\"interpolateboundary\"] [0 0] [] [] \"P\" [0 0 0  1 0 0  1 1 0  0 1 0]\nSubdivisionMesh \"catmull-clark\" [3 3] [0 1 2  0 2 3] "
                                  "[\"interpolateboundary\"] [0 0] [] [] \"P\" [0 0 0  1 0 0  1 1 0  0 1 0]\nMotionEnd"),
       warning(4, "SubdivisionMesh",
               "its motion samples do not tessellate alike (topology, or a dicing rate that changed with the shape): "
               "the first sample is built without motion blur"),
       [](const Scene& s) {
         EXPECT_GT(s.surfaces.triangles.size(), 0u);
         EXPECT_FALSE(s.has_motion());
       }},
      {"motion-points-count",
       "Shutter 0 1\n" + in_world("MotionBegin [0 1]\nPoints \"P\" [0 0 0] \"constantwidth\" [1]\n"
                                  "Points \"P\" [1 0 0  2 0 0] \"constantwidth\" [1]\nMotionEnd"),
       error(4, "Points",
             "its motion samples do not have as many points (\"P\"): the first sample is built without motion blur"),
       [](const Scene& s) {
         EXPECT_EQ(s.points.size(), 1u);
         EXPECT_FALSE(s.has_motion());
       }},
      {"motion-blur", "Shutter 0 1\n" + in_world("MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 0 2 0\nMotionEnd\n" + kLine3),
       std::nullopt,
       [](const Scene& s) {
         ASSERT_TRUE(s.curves.moving(0));
         Vec3f at[4];
         EXPECT_FLOAT_EQ(s.curves.control_points_at(0, 0.5f, at)[0].y, 1.0f) << "half-way at mid-shutter";
       }},
      {"camera-shutteropening", before_world("Camera \"main\" \"float[2] shutteropening\" [0.8 0.2]"),
       error(1, "Camera", "\"shutteropening\" [0.8 0.2] must be times 0 <= a <= b <= 1: ignored"),
       [](const Scene& s) { EXPECT_TRUE(s.output.shutter_opening.is_box()); }},
      {"camera-shutteropening-count", before_world("Camera \"main\" \"float[3] shutteropening\" [0.1 0.2 0.3]"),
       error(1, "Camera", "\"shutteropening\" takes 2 numbers (or RenderMan's 8), found 3: ignored"),
       [](const Scene& s) { EXPECT_TRUE(s.output.shutter_opening.is_box()); }},
      {"camera-shutteropening-curve",
       before_world("Camera \"main\" \"float[8] shutteropening\" [0.25 0.75 0 0 0 0 0 0]"),
       warning(1, "Camera",
               "the shutter curve's control points (numbers 3 to 8 of \"shutteropening\") are not supported: the "
               "shutter opens and closes linearly"),
       [](const Scene& s) {
         EXPECT_EQ(s.output.shutter_opening.fully_open, 0.25);
         EXPECT_EQ(s.output.shutter_opening.starts_closing, 0.75);
       }},
  };
}

}  // namespace darc::test
