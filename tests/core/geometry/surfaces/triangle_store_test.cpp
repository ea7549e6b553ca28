// TriangleStore, the one store of lowered surfaces, and SurfaceSet's dispatch over the kinds.
#include "core/geometry/surfaces/surface_set.h"
#include "core/geometry/surfaces/triangle_store.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace darc {
namespace {

// A unit square in z = 0 as two triangles, wound so that the face normal is +z.
TriangleMeshData unit_square() {
  TriangleMeshData m;
  m.P = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

Ray down_at(float x, float y) { return Ray{{x, y, 2}, {0, 0, -1}}; }

TEST(TriangleStore, HitsAtTheExactDistanceWithTheFaceNormalAndTheSurfaceParameters) {
  TriangleStore store;
  ASSERT_EQ(store.add(unit_square()), 2u);
  SurfaceHit h;
  ASSERT_TRUE(store.intersect(0, down_at(0.75f, 0.25f), h));
  EXPECT_FLOAT_EQ(h.t, 2.0f);
  EXPECT_EQ(h.ng, (Vec3f{0, 0, 1}));
  EXPECT_FLOAT_EQ(h.u, 0.75f);
  EXPECT_FLOAT_EQ(h.v, 0.25f);
  EXPECT_FALSE(store.intersect(0, down_at(0.25f, 0.75f), h)) << "that point is in the other triangle";
  EXPECT_TRUE(store.intersect(1, down_at(0.25f, 0.75f), h));
  Ray short_ray = down_at(0.75f, 0.25f);
  short_ray.tmax = 1.5f;
  EXPECT_FALSE(store.intersect(0, short_ray, h)) << "beyond tmax";
}

TEST(TriangleStore, NoRayFallsThroughTheSharedDiagonal) {
  TriangleStore store;
  store.add(unit_square());
  // Rays along and next to the diagonal x = y, where the two triangles meet.
  int misses = 0;
  for (int i = 1; i < 1000; ++i) {
    const float x = float(i) / 1000.0f;
    for (float offset : {0.0f, 1e-7f, -1e-7f}) {
      SurfaceHit h;
      const Ray r = down_at(x, x + offset);
      if (!store.intersect(0, r, h) && !store.intersect(1, r, h)) ++misses;
    }
  }
  EXPECT_EQ(misses, 0);
}

TEST(TriangleStore, DegenerateAndOutOfRangeTrianglesAreDropped) {
  TriangleMeshData m = unit_square();
  m.P.push_back({2, 2, 0});
  m.P.push_back({std::numeric_limits<float>::quiet_NaN(), 0, 0});
  m.indices.insert(m.indices.end(), {0, 2, 4});   // collinear: zero area
  m.indices.insert(m.indices.end(), {0, 1, 5});   // a NaN vertex
  m.indices.insert(m.indices.end(), {0, 1, 99});  // no such vertex
  TriangleStore store;
  EXPECT_EQ(store.add(m), 2u);
  EXPECT_EQ(store.size(), 2u);
}

TEST(TriangleStore, ShadingNormalsAreInterpolatedAndStayOnTheFaceSide) {
  TriangleMeshData m;
  m.P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const float s = std::sqrt(0.5f);
  m.N = {{0, 0, 1}, {s, 0, s}, {0, s, s}};
  m.indices = {0, 1, 2};
  TriangleStore store;
  store.add(m);
  const Vec3f at_vertex = store.shading_normal(0, {1, 0, 0});
  EXPECT_NEAR(at_vertex.x, s, 1e-6f);
  EXPECT_NEAR(at_vertex.z, s, 1e-6f);
  const Vec3f inside = store.shading_normal(0, {0.25f, 0.25f, 0.1f});  // above the plane: projected
  EXPECT_NEAR(length(inside), 1.0f, 1e-6f);
  EXPECT_GT(inside.x, 0);
  EXPECT_NEAR(inside.x, inside.y, 1e-6f) << "symmetric point, symmetric normal";
  // The same triangle wound the other way: its face normal is -z and the normals follow it.
  m.indices = {0, 2, 1};
  TriangleStore reversed;
  reversed.add(m);
  EXPECT_EQ(reversed.face_normal(0), (Vec3f{0, 0, -1}));
  EXPECT_LT(reversed.shading_normal(0, {0.25f, 0.25f, 0}).z, 0);
  // Without vertex normals: the face normal.
  TriangleStore flat;
  flat.add(unit_square());
  EXPECT_EQ(flat.shading_normal(0, {0.5f, 0.2f, 0}), (Vec3f{0, 0, 1}));
}

TEST(TriangleStore, BoundsContainTheTriangle) {
  TriangleStore store;
  TriangleMeshData m = unit_square();
  for (Vec3f& p : m.P) p = p * 1000.0f + Vec3f{1e4f, 0, 0};
  store.add(m);
  const BBox b = store.bounds(0);
  EXPECT_LE(b.lo.x, 1e4f);
  EXPECT_GE(b.hi.x, 1.1e4f);
  EXPECT_LE(b.lo.z, 0.0f);
  EXPECT_GE(b.hi.z, 0.0f);
}

TEST(SurfaceSet, DispatchesByIndexInKindOrder) {
  SurfaceSet set;
  set.spheres.push_back(Sphere::make(1, -1, 1, 360, Matrix4{}));
  set.sphere_material.push_back(7);
  set.polygons.push_back(*PolygonShape::make({{{5, 0, 0}, {6, 0, 0}, {6, 1, 0}}}));
  set.polygon_material.push_back(8);
  set.triangles.add(unit_square());
  set.triangle_material.assign(2, 9);
  ASSERT_EQ(set.size(), 4u);
  EXPECT_EQ(set.material(0), 7u);
  EXPECT_EQ(set.material(1), 8u);
  EXPECT_EQ(set.material(3), 9u);
  EXPECT_FALSE(set.is_flat(0));
  EXPECT_TRUE(set.is_flat(1));
  EXPECT_TRUE(set.is_flat(2));
  SurfaceHit h;
  EXPECT_TRUE(set.intersect(0, Ray{{0, 0, 5}, {0, 0, -1}}, h));
  EXPECT_FLOAT_EQ(h.t, 4.0f);
  EXPECT_TRUE(set.intersect(3, down_at(0.2f, 0.7f), h));
  EXPECT_FALSE(set.intersect(2, down_at(0.2f, 0.7f), h));
  EXPECT_EQ(set.geometric_normal(3, {0.2f, 0.7f, 0}), (Vec3f{0, 0, 1}));
  const BBox b = set.bounds(1);
  EXPECT_GE(b.hi.x, 6.0f);
}

// The unit square at shutter open, tilted and moved by +2 in x at close.
std::vector<TriangleMeshData> moving_square() {
  TriangleMeshData close = unit_square();
  for (Vec3f& p : close.P) p = {p.x + 2, p.y, p.x};  // moved, and tilted about the y axis
  return {unit_square(), close};
}

TEST(TriangleStore, AMovingMeshIsWhereItsKeysPutItAtTheRaysTime) {
  TriangleStore store;
  const std::vector<float> times{0, 1};
  const std::vector<TriangleMeshData> keys = moving_square();
  ASSERT_EQ(store.add_moving(times, keys), 2u);
  store.add(unit_square());  // a still mesh after it
  ASSERT_TRUE(store.has_motion());
  EXPECT_TRUE(store.moving(0));
  EXPECT_FALSE(store.moving(2));
  SurfaceHit h;
  Ray ray = down_at(2.5f, 0.25f);
  ray.time = 1.0f;
  ASSERT_TRUE(store.intersect(0, ray, h));
  EXPECT_FLOAT_EQ(h.t, 2.0f - 0.5f) << "the tilted square at x = 2.5 lies at z = 0.5";
  EXPECT_NEAR(h.ng.x, -std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(h.ng.z, std::sqrt(0.5f), 1e-6f);
  ray.time = 0.0f;
  EXPECT_FALSE(store.intersect(0, ray, h));
  ray = down_at(1.25f, 0.25f);
  ray.time = 0.5f;
  EXPECT_TRUE(store.intersect(0, ray, h)) << "half way";
  // The box holds both keys; the still square's box is its own.
  EXPECT_LE(store.bounds(0).lo.x, 0.0f);
  EXPECT_GE(store.bounds(0).hi.x, 3.0f);
  EXPECT_LE(store.bounds(2).hi.x, 1.0f + 1e-5f);
  // Corners shared by the two triangles are bitwise the same at any time (watertight coverage).
  for (float t : {0.0f, 0.3f, 0.77f, 1.0f}) {
    EXPECT_EQ(store.corner(0, 0, t), store.corner(1, 0, t));
    EXPECT_EQ(store.corner(0, 2, t), store.corner(1, 1, t));
  }
}

TEST(TriangleStore, KeysThatAgreeMakeAStillMeshAndANonFiniteKeyDropsItsTriangles) {
  TriangleStore still;
  const std::vector<float> times{0, 1};
  const std::vector<TriangleMeshData> same{unit_square(), unit_square()};
  EXPECT_EQ(still.add_moving(times, same), 2u);
  EXPECT_FALSE(still.has_motion());
  TriangleStore broken;
  std::vector<TriangleMeshData> keys = moving_square();
  keys[1].P[3].x = std::numeric_limits<float>::infinity();  // the second triangle's corner
  EXPECT_EQ(broken.add_moving(times, keys), 1u);
}

}  // namespace
}  // namespace darc
