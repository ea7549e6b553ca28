// Inputs found by the fuzz targets (fuzz/, docs/fuzzing.md): each one failed once (a crash, an
// out-of-memory, a sanitizer report) and must now be a clear error in its request.
#include <gtest/gtest.h>

#include <string>

#include "support/scenes_from_rib.h"

namespace darc::test {
namespace {

// The first error (a default Diagnostic, with an empty message, when there is none).
Diagnostic first_error(const Built& b) {
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error) return d;
  return Diagnostic{Severity::Error, {}, "", ""};
}

// darc_fuzz_scene: out-of-memory (malloc of 8 GB for the loop's vertex indices).
TEST(FuzzRegressions, GeneralPolygonWithMoreVerticesThanPointsFailsBeforeAllocating) {
  Built b = build("WorldBegin\nGeneralPolygon [2000000000] \"P\" [0 0 0 1 0 0 0 1 0]\nWorldEnd\n");
  // The ErrorHandler "print" policy: the request is skipped, its frame renders without it.
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(b.scenes[0].surfaces.polygons.empty());
  const Diagnostic error = first_error(b);
  EXPECT_EQ(error.message, "the loops have 2000000000 vertices but only 3 points are given");
  EXPECT_EQ(error.request, "GeneralPolygon");
  EXPECT_EQ(error.loc.line, 2);
}

// darc_fuzz_scene: heap-use-after-free. An object left open across WorldBegin was freed by
// WorldEnd (which drops the world's objects) while the builder still recorded into it.
TEST(FuzzRegressions, WorldBeginInsideAnObjectIsAnError) {
  Built b = build("ObjectBegin \"a\"\nWorldBegin\nWorldEnd\nSphere 1 -1 1 360\nObjectEnd\n");
  EXPECT_TRUE(b.scenes.empty());
  const Diagnostic error = first_error(b);
  EXPECT_EQ(error.message, "WorldBegin inside an ObjectBegin block");
  EXPECT_EQ(error.loc.line, 2);
}

// Objects may still be defined before the world block and used in it.
TEST(FuzzRegressions, ObjectsBeforeTheWorldBlockStillWork) {
  Built b = build("ObjectBegin \"a\" Sphere 1 -1 1 360 ObjectEnd\nWorldBegin ObjectInstance \"a\" WorldEnd\n");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.spheres.size(), 1u);
}

// darc_fuzz_scene: null Scene (UBSan). A motion block of quadrics before WorldBegin (where a
// camera's block goes): its samples were tessellated at MotionEnd before the builder checked that
// a world (and its scene) was there.
TEST(FuzzRegressions, AMotionBlockOfPrimitivesBeforeTheWorldIsAnError) {
  for (const std::string samples : {"Sphere 1 -1 1 360\nSphere 2 -2 2 360\n", "Points \"P\" [0 0 0]\nPoints \"P\" [1 0 0]\n",
                                    "Polygon \"P\" [0 0 0 1 0 0 0 1 0]\nPolygon \"P\" [0 0 0 2 0 0 0 1 0]\n"}) {
    Built b = build("Shutter 0 1\nMotionBegin [0 1]\n" + samples + "MotionEnd\nWorldBegin\nWorldEnd\n");
    ASSERT_EQ(b.scenes.size(), 1u) << samples;
    EXPECT_EQ(b.scenes[0].surfaces.size() + b.scenes[0].points.size(), 0u) << samples;
    const Diagnostic error = first_error(b);
    EXPECT_NE(error.message.find("outside WorldBegin/WorldEnd"), std::string::npos) << samples << error.message;
  }
}

}  // namespace
}  // namespace darc::test
