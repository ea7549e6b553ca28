// The quadric requests through SceneBuilder from RIB text: each builds one analytic surface in
// world space with the attributes of its block, object instances replay them, and degenerate
// or malformed ones add nothing.
#include <gtest/gtest.h>

#include <string>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

bool has_error(const Built& b, const std::string& fragment) {
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error && d.str().find(fragment) != std::string::npos) return true;
  return false;
}

bool mentions(const Built& b, const std::string& fragment) {
  for (const Diagnostic& d : b.diagnostics)
    if (d.str().find(fragment) != std::string::npos) return true;
  return false;
}

void expect_box_near(const BBox& box, const Vec3f& lo, const Vec3f& hi) {
  constexpr float kTol = 1e-4f;
  EXPECT_NEAR(box.lo.x, lo.x, kTol);
  EXPECT_NEAR(box.lo.y, lo.y, kTol);
  EXPECT_NEAR(box.lo.z, lo.z, kTol);
  EXPECT_NEAR(box.hi.x, hi.x, kTol);
  EXPECT_NEAR(box.hi.y, hi.y, kTol);
  EXPECT_NEAR(box.hi.z, hi.z, kTol);
}

TEST(SceneBuilderQuadrics, EachRequestBuildsItsQuadricInWorldSpace) {
  // Each moved 10 along x; the boxes are the full revolutions' object boxes, moved.
  struct Case {
    const char* rib;
    QuadricKind kind;
    Vec3f lo, hi;
  } cases[] = {
      {"Cone 2 0.5 360", QuadricKind::Cone, {9.5f, -0.5f, 0}, {10.5f, 0.5f, 2}},
      {"Cylinder 0.5 -1 2 360", QuadricKind::Cylinder, {9.5f, -0.5f, -1}, {10.5f, 0.5f, 2}},
      {"Disk 0.25 0.5 360", QuadricKind::Disk, {9.5f, -0.5f, 0.25f}, {10.5f, 0.5f, 0.25f}},
      {"Paraboloid 0.5 0 2 360", QuadricKind::Paraboloid, {9.5f, -0.5f, 0}, {10.5f, 0.5f, 2}},
      {"Hyperboloid 0.5 0 -1  0 0.25 1  360", QuadricKind::Hyperboloid, {9.5f, -0.5f, -1}, {10.5f, 0.5f, 1}},
      {"Torus 1 0.25 0 360 360", QuadricKind::Torus, {8.75f, -1.25f, -0.25f}, {11.25f, 1.25f, 0.25f}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.rib);
    Built b = build(std::string("WorldBegin Translate 10 0 0 Color [0.2 0.4 0.6] ") + c.rib + " WorldEnd");
    ASSERT_EQ(b.scenes.size(), 1u);
    const SurfaceSet& s = b.scenes[0].surfaces;
    ASSERT_EQ(s.quadrics.size(), 1u);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s.quadrics[0].kind, c.kind);
    expect_box_near(s.bounds(0), c.lo, c.hi);
    const Material& m = b.scenes[0].materials[s.material(0)];
    EXPECT_NEAR(m.color.y, 0.4f, 1e-6f);
    EXPECT_FALSE(mentions(b, "not supported"));
  }
}

TEST(SceneBuilderQuadrics, HitsComeThroughTheSurfaceSet) {
  Built b = build("WorldBegin Translate 0 0 5 Disk 0 1 360 WorldEnd");
  ASSERT_EQ(b.scenes.size(), 1u);
  const SurfaceSet& s = b.scenes[0].surfaces;
  SurfaceHit h;
  ASSERT_TRUE(s.intersect(0, Ray{{0.5f, 0, 0}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.t, 5.0f, 1e-5f);
  EXPECT_NEAR(s.geometric_normal(0, h.p).z, 1.0f, 1e-6f);
  EXPECT_TRUE(s.is_flat(0)) << "a disk cannot be hit again by a ray leaving it";
  Built torus = build("WorldBegin Torus 1 0.25 0 360 360 WorldEnd");
  EXPECT_FALSE(torus.scenes[0].surfaces.is_flat(0));
}

TEST(SceneBuilderQuadrics, ObjectInstancesReplayQuadrics) {
  Built b = build(R"(WorldBegin
ObjectBegin "ring" Torus 1 0.25 0 360 360 Cylinder 0.5 0 1 360 ObjectEnd
Translate 5 0 0 ObjectInstance "ring"
Translate 5 0 0 ObjectInstance "ring"
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const SurfaceSet& s = b.scenes[0].surfaces;
  ASSERT_EQ(s.quadrics.size(), 4u);
  EXPECT_NEAR(s.quadrics[0].bounds().center().x, 5.0f, 1e-4f);
  EXPECT_NEAR(s.quadrics[2].bounds().center().x, 10.0f, 1e-4f);
}

TEST(SceneBuilderQuadrics, OrientationAndSidesReachTheMaterial) {
  Built b = build(R"(WorldBegin
Cylinder 1 0 1 360
ReverseOrientation Cylinder 1 0 1 360
Sides 1 Cone 1 1 360
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& s = b.scenes[0];
  EXPECT_FALSE(s.materials[s.surfaces.quadric_material[0]].flip_normals);
  EXPECT_TRUE(s.materials[s.surfaces.quadric_material[1]].flip_normals);
  EXPECT_EQ(s.materials[s.surfaces.quadric_material[2]].sides, 1);
}

TEST(SceneBuilderQuadrics, DegenerateQuadricsAddNothingAndAreNotErrors) {
  Built b = build(R"(WorldBegin
Cone 1 0 360
Cylinder 1 0.5 0.5 360
Disk 0 1 0
Paraboloid 1 0 0 360
Hyperboloid 0 0 0  0 0 1  360
Torus 1 0 0 360 360
WorldEnd)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.size(), 0u);
  for (const Diagnostic& d : b.diagnostics) EXPECT_NE(d.severity, Severity::Error) << d.str();
}

TEST(SceneBuilderQuadrics, WrongArgumentsAreParserErrors) {
  Built b = build("WorldBegin\nCone 1 1\nTorus 1 0.25 0 360\nDisk 0 1 360\nWorldEnd\n");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.quadrics.size(), 1u) << "only the well-formed Disk";
  EXPECT_TRUE(has_error(b, "Cone: expected 3 numbers"));
  EXPECT_TRUE(has_error(b, "Torus: expected 5 numbers"));
}

TEST(SceneBuilderQuadrics, BeyondTheFloatRangeIsAnError) {
  Built b = build("WorldBegin Scale 1e30 1e30 1e30 Cylinder 1e30 0 1 360 Disk 0 1 360 WorldEnd");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(has_error(b, "Cylinder lies beyond the float range"));
  EXPECT_EQ(b.scenes[0].surfaces.quadrics.size(), 1u);
}

}  // namespace
}  // namespace darc
