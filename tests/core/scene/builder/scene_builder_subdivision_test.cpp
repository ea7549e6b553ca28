// SceneBuilder's SubdivisionMesh: from RIB text to the scene's triangle store, with the
// request's errors and warnings reported at its position and its colours as materials.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/geometry/surfaces/subdivision/subdivision_surface.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

const std::string kCube =
    "SubdivisionMesh \"catmull-clark\" [4 4 4 4 4 4] [0 3 2 1  4 5 6 7  0 1 5 4  1 2 6 5  2 3 7 6  3 0 4 7]";
const std::string kCubeP = "\"P\" [-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1]";
// Triangles of the cube's limit surface: 24 quads after the first level, 4 per quad per further
// level, 2 triangles per quad.
const size_t kCubeTriangles = size_t(2 * 24) << (2 * (subdivision_levels_for(24) - 1));

std::string world(const std::string& body) { return "WorldBegin\n" + body + "\nWorldEnd\n"; }

size_t count_with(const test::Built& b, Severity severity, const std::string& text) {
  return std::count_if(b.diagnostics.begin(), b.diagnostics.end(), [&](const Diagnostic& d) {
    return d.severity == severity && d.str().find(text) != std::string::npos;
  });
}

TEST(SceneBuilderSubdivision, CubeBecomesItsLimitTriangles) {
  test::Built b = test::build(world("Color [0.2 0.4 0.6]\n" + kCube + " " + kCubeP));
  ASSERT_EQ(b.scenes.size(), 1u);
  const SurfaceSet& s = b.scenes[0].surfaces;
  EXPECT_EQ(s.triangles.size(), kCubeTriangles);
  ASSERT_EQ(s.triangle_material.size(), kCubeTriangles);
  EXPECT_EQ(b.scenes[0].materials[s.triangle_material[0]].color, (Vec3f{0.2f, 0.4f, 0.6f}));
  EXPECT_EQ(count_with(b, Severity::Error, ""), 0u);
  EXPECT_EQ(count_with(b, Severity::Warning, "SubdivisionMesh"), 0u);
}

TEST(SceneBuilderSubdivision, UniformColourGivesOneMaterialPerDistinctValue) {
  // Face 1 (z = 1) red, the others green; constant Os for all.
  test::Built b = test::build(world(kCube + " " + kCubeP +
                                    " \"uniform color Cs\" [0 1 0  1 0 0  0 1 0  0 1 0  0 1 0  0 1 0]"
                                    " \"constant color Os\" [0.5 0.5 0.5]"));
  ASSERT_EQ(b.scenes.size(), 1u);
  const Scene& scene = b.scenes[0];
  ASSERT_EQ(scene.surfaces.triangles.size(), kCubeTriangles);
  size_t red = 0, green = 0;
  for (uint32_t m : scene.surfaces.triangle_material) {
    const Material& material = scene.materials[m];
    EXPECT_EQ(material.opacity, (Vec3f{0.5f, 0.5f, 0.5f}));
    red += material.color == Vec3f{1, 0, 0};
    green += material.color == Vec3f{0, 1, 0};
  }
  EXPECT_EQ(red, kCubeTriangles / 6);
  EXPECT_EQ(green, kCubeTriangles * 5 / 6);
}

TEST(SceneBuilderSubdivision, VaryingColourAndOtherVariablesWarnOnce) {
  const std::string mesh = kCube + " " + kCubeP +
                           " \"vertex color Cs\" [0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0]"
                           " \"facevarying float dirt\" [0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0]\n";
  test::Built b = test::build(world("Color [1 1 0]\n" + mesh + mesh));
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.triangles.size(), 2 * kCubeTriangles);
  EXPECT_EQ(count_with(b, Severity::Warning, "\"Cs\" (vertex) is not interpolated"), 1u);
  EXPECT_EQ(count_with(b, Severity::Warning, "\"dirt\" is not used"), 1u);
  EXPECT_EQ(b.scenes[0].materials[b.scenes[0].surfaces.triangle_material[0]].color, (Vec3f{1, 1, 0}));
}

TEST(SceneBuilderSubdivision, TessellationWarningsAreReportedAtTheRequest) {
  test::Built b = test::build(world(kCube + " [\"sparkle\"] [0 0 0] [] [] [] " + kCubeP));
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.triangles.size(), kCubeTriangles);
  EXPECT_EQ(count_with(b, Severity::Warning, "test.rib:2:1: warning: SubdivisionMesh: unknown tag \"sparkle\""), 1u);
}

TEST(SceneBuilderSubdivision, BadMeshIsAnErrorAtTheRequest) {
  for (const std::string& bad : {
           kCube + " [\"crease\"] [1 1 0] [0] [2] [] " + kCubeP,  // a crease of one vertex
           std::string("SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] \"P\" [0 0 0  1 0 0  1 1 0]"),  // index 3
           std::string("SubdivisionMesh \"sqrt3\" [3] [0 1 2] \"P\" [0 0 0  1 0 0  1 1 0]"),
           kCube + " " + kCubeP + " \"uniform color Cs\" [1 0 0]",
           kCube + " " + kCubeP + " \"facevarying float[2] st\" [0 0  1 1]",  // 2 of 24 corners
           kCube + " " + kCubeP + " \"uniform float s\" [0 1 2]",             // 3 of 6 faces
           kCube + " " + kCubeP + " \"vertex float[3] st\" [0 0 0]",          // st is float[2]
           kCube,  // no P
       }) {
    SCOPED_TRACE(bad);
    test::Built b = test::build(world(bad));
    ASSERT_EQ(b.scenes.size(), 1u);
    EXPECT_EQ(count_with(b, Severity::Error, "test.rib:2:1"), 1u);
    EXPECT_EQ(b.scenes[0].surfaces.triangles.size(), 0u);
  }
}

// "st" reaches the triangle store as each vertex's (u, v), the texture coordinates of its
// triangles; without it the store keeps none for the mesh.
TEST(SceneBuilderSubdivision, StBecomesTheTrianglesTextureCoordinates) {
  const std::string st = " \"vertex float[2] st\" [0 0  1 0  1 1  0 1  0 0  1 0  1 1  0 1]";
  for (bool with_st : {false, true}) {
    test::Built b = test::build(world(kCube + " " + kCubeP + (with_st ? st : "")));
    ASSERT_EQ(b.scenes.size(), 1u);
    EXPECT_EQ(count_with(b, Severity::Error, ""), 0u);
    EXPECT_EQ(count_with(b, Severity::Warning, ""), 0u);
    const TriangleStore& triangles = b.scenes[0].surfaces.triangles;
    ASSERT_EQ(triangles.size(), kCubeTriangles);
    Vec2f uv, duv_dx, duv_dy;
    // The first triangle's first corner, wherever it is: st within the square the vertices span.
    const bool has = triangles.parameters(0, triangles.corner(0, 0), {}, {}, uv, duv_dx, duv_dy);
    EXPECT_EQ(has, with_st);
    if (has) {
      EXPECT_GE(uv.x, 0.0f);
      EXPECT_LE(uv.x, 1.0f);
      EXPECT_GE(uv.y, 0.0f);
      EXPECT_LE(uv.y, 1.0f);
    }
  }
}

TEST(SceneBuilderSubdivision, HoleTagWithTwoNargsPerTag) {
  // RI 3.2's nargs (integers, floats per tag) and no stringargs: faces 0 and 1 are holes.
  test::Built b = test::build(world(kCube + " [\"hole\"] [2 0] [0 1] [] " + kCubeP));
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(count_with(b, Severity::Error, ""), 0u);
  EXPECT_EQ(b.scenes[0].surfaces.triangles.size(), kCubeTriangles * 4 / 6);
}

TEST(SceneBuilderSubdivision, ObjectInstancesTessellateEachTime) {
  test::Built b = test::build(world("ObjectBegin 1\n" + kCube + " " + kCubeP +
                                    "\nObjectEnd\nObjectInstance 1\nTranslate 3 0 0\nObjectInstance 1"));
  ASSERT_EQ(b.scenes.size(), 1u);
  const SurfaceSet& s = b.scenes[0].surfaces;
  ASSERT_EQ(s.triangles.size(), 2 * kCubeTriangles);
  // The second instance is moved by the Translate.
  EXPECT_GT(s.triangles.bounds(uint32_t(kCubeTriangles)).lo.x, 1.5f);
  EXPECT_LT(s.triangles.bounds(0).hi.x, 1.0f);
}

}  // namespace
}  // namespace darc
