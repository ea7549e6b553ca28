// Texture coordinates on polygons (core/scene/builder/polygon_st.h): each face gets the affine
// map of its plane that fits its corners' "st" (or "s" and "t") of any storage class, and
// unusable primvars are reported.
#include <gtest/gtest.h>

#include "core/scene/builder/polygon_st.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

Param floats(const std::string& name, StorageClass storage, int size, std::vector<float> v) {
  Param p;
  p.name = name;
  p.decl = {storage, ParamType::Float, size};
  p.floats = std::move(v);
  return p;
}

// Two unit squares side by side in the z = 0 plane, sharing an edge: points 0-5.
const std::vector<Vec3f> kPoints = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
const std::vector<int> kLoops = {1, 1}, kVerts = {4, 4}, kIndices = {0, 1, 4, 3, 1, 2, 5, 4};

std::vector<PolygonShape> squares() {
  std::string error;
  std::vector<PolygonShape> shapes = make_points_general_polygons(kLoops, kVerts, kIndices, kPoints, error);
  EXPECT_TRUE(error.empty()) << error;
  return shapes;
}

float s_at(const PolygonShape& p, Vec3f q) { return dot(p.s_gradient, q) + p.s_offset; }
float t_at(const PolygonShape& p, Vec3f q) { return dot(p.t_gradient, q) + p.t_offset; }

TEST(PolygonSt, VertexStIsInterpolatedExactlyOnAParallelogram) {
  std::vector<PolygonShape> shapes = squares();
  ParamList params;
  // s = x / 2, t = 1 - y at every point.
  params.params = {floats("st", StorageClass::Vertex, 2, {0, 1, 0.5f, 1, 1, 1, 0, 0, 0.5f, 0, 1, 0})};
  EXPECT_EQ(fit_polygon_st(params, kLoops, kVerts, kIndices, kPoints, shapes), "");
  ASSERT_EQ(shapes.size(), 2u);
  for (const PolygonShape& p : shapes) {
    ASSERT_TRUE(p.has_st);
    for (Vec3f q : {Vec3f{0.25f, 0.5f, 0}, Vec3f{1.75f, 0.1f, 0}}) {
      EXPECT_NEAR(s_at(p, q), q.x / 2, 1e-6f);
      EXPECT_NEAR(t_at(p, q), 1 - q.y, 1e-6f);
    }
  }
}

TEST(PolygonSt, FaceVaryingStGivesEachFaceItsOwnMap) {
  std::vector<PolygonShape> shapes = squares();
  ParamList params;
  // Each face maps to the whole texture: s = x - x0 per face.
  params.params = {floats("st", StorageClass::FaceVarying, 2, {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1})};
  EXPECT_EQ(fit_polygon_st(params, kLoops, kVerts, kIndices, kPoints, shapes), "");
  EXPECT_NEAR(s_at(shapes[0], {0.5f, 0.5f, 0}), 0.5f, 1e-6f);
  EXPECT_NEAR(s_at(shapes[1], {1.5f, 0.5f, 0}), 0.5f, 1e-6f);
  EXPECT_NEAR(t_at(shapes[1], {1.5f, 0.25f, 0}), 0.25f, 1e-6f);
}

TEST(PolygonSt, SAndTApartAndUniformValuesWork) {
  std::vector<PolygonShape> shapes = squares();
  ParamList params;
  params.params = {floats("s", StorageClass::Uniform, 1, {0.2f, 0.7f}), floats("t", StorageClass::Constant, 1, {0.4f})};
  EXPECT_EQ(fit_polygon_st(params, kLoops, kVerts, kIndices, kPoints, shapes), "");
  EXPECT_NEAR(s_at(shapes[1], {1.2f, 0.3f, 0}), 0.7f, 1e-6f);
  EXPECT_NEAR(t_at(shapes[0], {0.2f, 0.9f, 0}), 0.4f, 1e-6f);
  EXPECT_NEAR(length(shapes[0].s_gradient), 0.0f, 1e-6f);
}

TEST(PolygonSt, AMissizedPrimvarIsReportedAndNoFaceGetsCoordinates) {
  std::vector<PolygonShape> shapes = squares();
  ParamList params;
  params.params = {floats("st", StorageClass::FaceVarying, 2, {0, 0, 1, 0})};
  EXPECT_EQ(fit_polygon_st(params, kLoops, kVerts, kIndices, kPoints, shapes),
            "\"st\" (facevarying) has 2 values, needs 8: ignored");
  for (const PolygonShape& p : shapes) EXPECT_FALSE(p.has_st);
}

TEST(PolygonSt, TheBuilderWarnsAtTheRequest) {
  const test::Built built = test::build(
      "WorldBegin\nPolygon \"P\" [0 0 0  1 0 0  1 1 0] \"st\" [0 0  1 0]\nWorldEnd\n");
  ASSERT_GE(built.diagnostics.size(), 1u);  // then "nothing renderable": the polygon is at the eye
  EXPECT_EQ(built.diagnostics[0].loc.line, 2);
  EXPECT_EQ(built.diagnostics[0].message, "\"st\" (varying) has 2 values, needs 3: ignored");
}

}  // namespace
}  // namespace darc
