// Patch, PatchMesh and NuPatch through the parser and SceneBuilder: they reach the triangle store
// in world space with the current Basis, their bad arguments are errors with the request's
// position, interpolated colours warn once, and they replay from ObjectBegin blocks.
#include <gtest/gtest.h>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

BBox triangle_bounds(const Scene& s) {
  BBox box;
  for (uint32_t t = 0; t < s.surfaces.triangles.size(); ++t) box.extend(s.surfaces.triangles.bounds(t));
  return box;
}

std::vector<Diagnostic> of_severity(const Built& b, Severity severity) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == severity) out.push_back(d);
  return out;
}

// One error, at `position`, whose message contains `part`.
void expect_error(const std::string& world, const std::string& position, const std::string& part) {
  SCOPED_TRACE(world);
  Built b = build("WorldBegin\n" + world + "\nWorldEnd\n");
  const std::vector<Diagnostic> errors = of_severity(b, Severity::Error);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].loc.str(), position);
  EXPECT_NE(errors[0].message.find(part), std::string::npos) << errors[0].message;
}

TEST(SceneBuilderPatches, BilinearPatchMeshIsInWorldSpace) {
  Built b = build(R"(WorldBegin
Translate 10 0 0
PatchMesh "bilinear" 3 "nonperiodic" 2 "nonperiodic" "P" [0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0]
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(of_severity(b, Severity::Error).empty());
  const Scene& s = b.scenes[0];
  EXPECT_EQ(s.surfaces.triangles.size(), 4u) << "two flat patches, two triangles each";
  EXPECT_EQ(s.surfaces.triangle_material.size(), 4u);
  const BBox box = triangle_bounds(s);
  EXPECT_NEAR(box.lo.x, 10, 1e-5);
  EXPECT_NEAR(box.hi.x, 12, 1e-5);
  EXPECT_NEAR(box.hi.y, 1, 1e-5);
}

TEST(SceneBuilderPatches, BicubicPatchUsesTheCurrentBasis) {
  // 4 x 4 points on the integer grid: a Bézier patch spans all of it, a B-spline one [1, 2]^2.
  const std::string grid =
      R"("P" [0 0 0 1 0 0 2 0 0 3 0 0  0 1 0 1 1 0 2 1 0 3 1 0  0 2 0 1 2 0 2 2 0 3 2 0  0 3 0 1 3 0 2 3 0 3 3 0])";
  Built bezier = build("WorldBegin\nPatch \"bicubic\" " + grid + "\nWorldEnd\n");
  Built bspline = build("WorldBegin\nBasis \"b-spline\" 1 \"b-spline\" 1\nPatch \"bicubic\" " + grid + "\nWorldEnd\n");
  ASSERT_EQ(bezier.scenes.size(), 1u);
  ASSERT_EQ(bspline.scenes.size(), 1u);
  const BBox a = triangle_bounds(bezier.scenes[0]), c = triangle_bounds(bspline.scenes[0]);
  EXPECT_NEAR(a.lo.x, 0, 1e-5);
  EXPECT_NEAR(a.hi.y, 3, 1e-5);
  EXPECT_NEAR(c.lo.x, 1, 1e-5);
  EXPECT_NEAR(c.hi.y, 2, 1e-5);
}

TEST(SceneBuilderPatches, NuPatchReachesTheTriangleStore) {
  // A bilinear NURBS (order 2) over part of its range: u in [0.5, 1] of [0, 1].
  Built b = build(R"(WorldBegin
NuPatch 2 2 [0 0 1 1] 0.5 1 2 2 [0 0 1 1] 0 1 "Pw" [0 0 0 1  2 0 0 1  0 2 0 1  2 2 0 1]
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(of_severity(b, Severity::Error).empty());
  EXPECT_EQ(b.scenes[0].surfaces.triangles.size(), 2u);
  const BBox box = triangle_bounds(b.scenes[0]);
  EXPECT_NEAR(box.lo.x, 1, 1e-5);
  EXPECT_NEAR(box.hi.x, 2, 1e-5);
}

TEST(SceneBuilderPatches, HeightFieldTakesXAndYFromTheMeshParameters) {
  Built b =
      build("WorldBegin\nPatchMesh \"bilinear\" 3 \"nonperiodic\" 2 \"nonperiodic\" \"Pz\" [0 1 0 0 1 0]\nWorldEnd\n");
  ASSERT_EQ(b.scenes.size(), 1u);
  const BBox box = triangle_bounds(b.scenes[0]);
  EXPECT_NEAR(box.lo.x, 0, 1e-6);
  EXPECT_NEAR(box.hi.x, 1, 1e-6);
  EXPECT_NEAR(box.hi.y, 1, 1e-6);
  EXPECT_NEAR(box.hi.z, 1, 1e-6);
}

TEST(SceneBuilderPatches, BadArgumentsAreErrorsAtTheRequest) {
  expect_error("Patch \"bicubical\" \"P\" [0 0 0 1 0 0 0 1 0 1 1 0]", "test.rib:2:1",
               "unknown patch type \"bicubical\"");
  expect_error("PatchMesh \"bilinear\" 2 \"wrapped\" 2 \"nonperiodic\" \"P\" [0 0 0 1 0 0 0 1 0 1 1 0]", "test.rib:2:1",
               "unknown uwrap \"wrapped\"");
  expect_error("PatchMesh \"bicubic\" 5 \"nonperiodic\" 4 \"nonperiodic\" \"P\" [0 0 0]", "test.rib:2:1", "4 + 3 k");
  expect_error("PatchMesh \"bilinear\" 2 \"nonperiodic\" 2 \"nonperiodic\" \"P\" [0 0 0 1 0 0 0 1 0]", "test.rib:2:1",
               "needs 4 points, found 3");
  expect_error("Patch \"bilinear\" \"Cs\" [1 0 0]", "test.rib:2:1", "Patch needs \"P\", \"Pw\" or \"Pz\"");
  expect_error("NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"Pz\" [0 0 0 0]", "test.rib:2:1",
               "NuPatch needs \"P\" or \"Pw\"");
  expect_error("NuPatch 2 2 [0 1 0 1] 0 1 2 2 [0 0 1 1] 0 1 \"P\" [0 0 0 1 0 0 0 1 0 1 1 0]", "test.rib:2:1",
               "uknot decreases");
  expect_error("NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 2 \"P\" [0 0 0 1 0 0 0 1 0 1 1 0]", "test.rib:2:1",
               "vmax <= 1");
}

TEST(SceneBuilderPatches, InterpolatedColoursWarnOnce) {
  Built b = build(R"(WorldBegin
Patch "bilinear" "P" [0 0 0 1 0 0 0 1 0 1 1 0] "varying color Cs" [1 0 0 0 1 0 0 0 1 1 1 1]
Patch "bilinear" "P" [0 0 0 1 0 0 0 1 0 1 1 0] "vertex color Cs" [1 0 0 0 1 0 0 0 1 1 1 1]
Patch "bilinear" "P" [0 0 0 1 0 0 0 1 0 1 1 0] "constant color Cs" [1 0 0]
WorldEnd)");
  const std::vector<Diagnostic> warnings = of_severity(b, Severity::Warning);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].loc.str(), "test.rib:2:1");
  EXPECT_NE(warnings[0].message.find("not supported on Patch: the Color and Opacity attributes are used"),
            std::string::npos);
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.triangles.size(), 6u) << "the patches are still built";
}

TEST(SceneBuilderPatches, ObjectInstancesReplayPatches) {
  Built b = build(R"(ObjectBegin "ground"
  Patch "bilinear" "P" [0 0 0 1 0 0 0 1 0 1 1 0]
ObjectEnd
WorldBegin
ObjectInstance "ground"
Translate 5 0 0
ObjectInstance "ground"
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(of_severity(b, Severity::Error).empty());
  EXPECT_EQ(b.scenes[0].surfaces.triangles.size(), 4u);
  EXPECT_NEAR(triangle_bounds(b.scenes[0]).hi.x, 6, 1e-5);
}

}  // namespace
}  // namespace darc
