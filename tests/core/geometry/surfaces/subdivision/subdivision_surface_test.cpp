#include "core/geometry/surfaces/subdivision/subdivision_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "core/geometry/surfaces/subdivision/catmull_clark_refinement.h"

namespace darc {
namespace {

// The cube [-1, 1]^3, every face wound so that its right-hand normal points out.
SubdivisionMeshRequest cube() {
  SubdivisionMeshRequest r;
  r.scheme = "catmull-clark";
  r.P = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  r.nvertices = {4, 4, 4, 4, 4, 4};
  r.vertices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  return r;
}

// An n x n grid of unit quads in the z = 0 plane, wound so that the normal is +z.
SubdivisionMeshRequest planar_grid(int n) {
  SubdivisionMeshRequest r;
  r.scheme = "catmull-clark";
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) r.P.push_back({float(i), float(j), 0});
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      int v = j * (n + 1) + i;
      r.nvertices.push_back(4);
      r.vertices.insert(r.vertices.end(), {v, v + 1, v + n + 2, v + n + 1});
    }
  }
  return r;
}

void add_tag(SubdivisionMeshRequest& r, const std::string& tag, std::vector<int> ints, std::vector<float> floats) {
  r.tags.push_back(tag);
  r.nargs.insert(r.nargs.end(), {int(ints.size()), int(floats.size()), 0});
  r.intargs.insert(r.intargs.end(), ints.begin(), ints.end());
  r.floatargs.insert(r.floatargs.end(), floats.begin(), floats.end());
}

// A pentagon with a triangle beside it (n-gons, an extraordinary vertex), in z = 0 wound for +z,
// its boundary interpolated.
SubdivisionMeshRequest pentagon_beside_a_triangle() {
  SubdivisionMeshRequest r;
  r.scheme = "catmull-clark";
  r.P = {{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}, {4, 3, 0}};
  r.nvertices = {5, 3};
  r.vertices = {0, 1, 2, 3, 4, 2, 5, 3};
  add_tag(r, "interpolateboundary", {}, {});
  return r;
}

void crease_every_cube_edge(SubdivisionMeshRequest& r, float sharpness) {
  for (auto [a, b] :
       {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}) {
    add_tag(r, "crease", {a, b}, {sharpness});
  }
}

bool has_point(const TriangleMeshData& m, Vec3f p, float tolerance = 1e-6f) {
  for (const Vec3f& q : m.P) {
    if (length(q - p) <= tolerance) return true;
  }
  return false;
}

Vec3f geometric_normal(const TriangleMeshData& m, size_t t) {
  const Vec3f& a = m.P[m.indices[3 * t]];
  return cross(m.P[m.indices[3 * t + 1]] - a, m.P[m.indices[3 * t + 2]] - a);
}

// Every normal unit length and finite, every index in range.
void expect_well_formed(const TriangleMeshData& m) {
  ASSERT_EQ(m.N.size(), m.P.size());
  for (const Vec3f& n : m.N) EXPECT_NEAR(length(n), 1.0f, 1e-5f);
  for (uint32_t i : m.indices) ASSERT_LT(i, m.P.size());
}

// The limit of the cube, by hand: after one level the face centre is a regular vertex with
// face point (0, 0, 1), edge points z = 3/4 and corner vertex points (5/9)(1, 1, 1), so the
// regular limit mask (16 v + 4 sum e + sum f) / 36 puts it at z = 68/81; the corner (valence 3:
// (9 v + 4 sum e + sum f) / 24 with v = 5/9, e = (3/4, 3/4, 0) and permutations, f the unit
// axes) goes to (1/2, 1/2, 1/2).
constexpr float kCubeFaceCentreLimit = 68.0f / 81.0f;

TEST(SubdivisionSurface, CubeLimitLiesBetweenItsFaceCentresAndCorners) {
  SubdivisionTessellation t = tessellate_subdivision_mesh(cube());
  ASSERT_TRUE(t.ok()) << t.error;
  EXPECT_EQ(t.levels, kMaxSubdivisionLevels);
  EXPECT_EQ(t.mesh.triangle_count(), size_t(2 * 24) << (2 * (t.levels - 1)));
  expect_well_formed(t.mesh);
  for (const Vec3f& p : t.mesh.P) {
    // Inside the cube (strictly: Catmull-Clark pulls every face in) and between the sphere
    // through the limit face centres and the one through the limit corners.
    EXPECT_LE(max_component(abs(p)), kCubeFaceCentreLimit + 1e-6f);
    EXPECT_GE(length(p), kCubeFaceCentreLimit - 1e-6f);
    EXPECT_LE(length(p), std::sqrt(3.0f) / 2.0f + 1e-6f);
  }
  EXPECT_TRUE(has_point(t.mesh, {0, 0, kCubeFaceCentreLimit}));
  EXPECT_TRUE(has_point(t.mesh, {-kCubeFaceCentreLimit, 0, 0}));
  EXPECT_TRUE(has_point(t.mesh, {0.5f, 0.5f, 0.5f}));
  EXPECT_TRUE(has_point(t.mesh, {-0.5f, 0.5f, -0.5f}));
}

TEST(SubdivisionSurface, CubeLimitIsSymmetric) {
  SubdivisionTessellation t = tessellate_subdivision_mesh(cube());
  ASSERT_TRUE(t.ok());
  for (const Vec3f& p : t.mesh.P) {
    EXPECT_TRUE(has_point(t.mesh, {-p.x, p.y, p.z}, 1e-5f));  // mirror in x
    EXPECT_TRUE(has_point(t.mesh, {p.y, p.z, p.x}, 1e-5f));   // the 3-fold turn about (1, 1, 1)
  }
}

TEST(SubdivisionSurface, CubeNormalsAtFaceCentresAreTheFaceNormals) {
  SubdivisionTessellation t = tessellate_subdivision_mesh(cube());
  ASSERT_TRUE(t.ok());
  int found = 0;
  for (size_t i = 0; i < t.mesh.P.size(); ++i) {
    const Vec3f& p = t.mesh.P[i];
    for (int axis = 0; axis < 3; ++axis) {
      if (std::abs(std::abs(p[axis]) - kCubeFaceCentreLimit) > 1e-6f) continue;
      Vec3f face_normal;
      face_normal[axis] = p[axis] > 0 ? 1.0f : -1.0f;
      EXPECT_NEAR(length(t.mesh.N[i] - face_normal), 0.0f, 1e-5f);
      ++found;
    }
  }
  EXPECT_EQ(found, 6);
  // And at the limit corners the normal points along the diagonal.
  for (size_t i = 0; i < t.mesh.P.size(); ++i) {
    if (length(t.mesh.P[i] - Vec3f{0.5f, 0.5f, 0.5f}) < 1e-6f) {
      EXPECT_NEAR(length(t.mesh.N[i] - normalize(Vec3f{1, 1, 1})), 0.0f, 1e-5f);
    }
  }
}

TEST(SubdivisionSurface, TrianglesWindAsTheControlFaces) {
  SubdivisionTessellation out = tessellate_subdivision_mesh(cube());
  SubdivisionMeshRequest reversed = cube();
  for (size_t f = 0; f < 6; ++f) std::reverse(reversed.vertices.begin() + 4 * f, reversed.vertices.begin() + 4 * f + 4);
  SubdivisionTessellation in = tessellate_subdivision_mesh(reversed);
  ASSERT_TRUE(out.ok() && in.ok());
  for (size_t k = 0; k < out.mesh.triangle_count(); ++k) {
    Vec3f centre = out.mesh.P[out.mesh.indices[3 * k]];
    EXPECT_GT(dot(geometric_normal(out.mesh, k), centre), 0.0f);
    EXPECT_GT(dot(out.mesh.N[out.mesh.indices[3 * k]], centre), 0.0f);
  }
  for (size_t k = 0; k < in.mesh.triangle_count(); ++k) {
    Vec3f centre = in.mesh.P[in.mesh.indices[3 * k]];
    EXPECT_LT(dot(geometric_normal(in.mesh, k), centre), 0.0f);
    EXPECT_LT(dot(in.mesh.N[in.mesh.indices[3 * k]], centre), 0.0f);
  }
}

TEST(SubdivisionSurface, TetrahedronOfTriangles) {
  // The realworld scenes' mesh: four triangles (each becomes three quads), closed.
  SubdivisionMeshRequest r;
  r.scheme = "catmull-clark";
  r.nvertices = {3, 3, 3, 3};
  r.vertices = {0, 1, 3, 1, 2, 3, 2, 0, 3, 2, 1, 0};
  r.P = {{1, 0, 0}, {-0.5f, 1, 0}, {-0.5f, -1, 0}, {0, 0, 1}};
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  EXPECT_EQ(t.mesh.triangle_count(), size_t(2 * 12) << (2 * (t.levels - 1)));
  expect_well_formed(t.mesh);
  // Shading normals agree with the facets they shade.
  for (size_t k = 0; k < t.mesh.triangle_count(); ++k) {
    Vec3f n = normalize(geometric_normal(t.mesh, k));
    for (int c = 0; c < 3; ++c) EXPECT_GT(dot(n, t.mesh.N[t.mesh.indices[3 * k + c]]), 0.9f);
  }
}

TEST(SubdivisionSurface, PlanarGridStaysPlanar) {
  for (bool interpolate : {false, true}) {
    SubdivisionMeshRequest r = planar_grid(3);
    if (interpolate) add_tag(r, "interpolateboundary", {}, {});
    SubdivisionTessellation t = tessellate_subdivision_mesh(r);
    ASSERT_TRUE(t.ok()) << t.error;
    ASSERT_GT(t.mesh.triangle_count(), 0u);
    expect_well_formed(t.mesh);
    for (const Vec3f& p : t.mesh.P) EXPECT_EQ(p.z, 0.0f);
    for (const Vec3f& n : t.mesh.N) EXPECT_NEAR(length(n - Vec3f{0, 0, 1}), 0.0f, 1e-6f);
    // Without boundary interpolation only the middle face (the one not touching the boundary)
    // is drawn; with it, all nine, reaching the outer corners.
    ASSERT_EQ(t.triangle_control_face.size(), t.mesh.triangle_count());
    std::set<uint32_t> drawn(t.triangle_control_face.begin(), t.triangle_control_face.end());
    EXPECT_EQ(drawn.size(), interpolate ? 9u : 1u);
    if (!interpolate) {
      EXPECT_EQ(*drawn.begin(), 4u);
    }
    EXPECT_EQ(has_point(t.mesh, {0, 0, 0}), interpolate);
    EXPECT_EQ(has_point(t.mesh, {3, 3, 0}), interpolate);
  }
}

TEST(SubdivisionSurface, PlanarFansAroundExtraordinaryVerticesStayPlanar) {
  // k quads around a centre vertex of valence k (3, 5, 6: the extraordinary masks), in z = 0,
  // and a pentagon with a triangle beside it (n-gons), all wound for +z.
  for (int k : {3, 5, 6}) {
    SCOPED_TRACE(k);
    SubdivisionMeshRequest r;
    r.scheme = "catmull-clark";
    r.P.push_back({0, 0, 0});
    for (int i = 0; i < 2 * k; ++i) {
      float angle = float(i) * 3.14159265f / float(k), radius = i % 2 == 0 ? 1.0f : 1.5f;
      r.P.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
    for (int i = 0; i < k; ++i) {
      r.nvertices.push_back(4);
      r.vertices.insert(r.vertices.end(), {0, 1 + 2 * i, 2 + 2 * i, 1 + (2 * i + 2) % (2 * k)});
    }
    add_tag(r, "interpolateboundary", {1}, {});
    SubdivisionTessellation t = tessellate_subdivision_mesh(r);
    ASSERT_TRUE(t.ok()) << t.error;
    expect_well_formed(t.mesh);
    for (const Vec3f& p : t.mesh.P) EXPECT_EQ(p.z, 0.0f);
    for (const Vec3f& n : t.mesh.N) EXPECT_NEAR(length(n - Vec3f{0, 0, 1}), 0.0f, 1e-5f);
    EXPECT_TRUE(has_point(t.mesh, {0, 0, 0}));  // the centre's limit, by symmetry
  }
  SubdivisionMeshRequest r = pentagon_beside_a_triangle();
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  expect_well_formed(t.mesh);
  for (const Vec3f& p : t.mesh.P) EXPECT_EQ(p.z, 0.0f);
  for (const Vec3f& n : t.mesh.N) EXPECT_NEAR(length(n - Vec3f{0, 0, 1}), 0.0f, 1e-5f);
  for (size_t k = 0; k < t.mesh.triangle_count(); ++k) EXPECT_GT(geometric_normal(t.mesh, k).z, 0.0f);
}

TEST(SubdivisionSurface, FullyCreasedCubeKeepsItsCornersAndFaces) {
  SubdivisionMeshRequest r = cube();
  crease_every_cube_edge(r, kInfiniteSharpness);
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  expect_well_formed(t.mesh);
  for (const Vec3f& p : t.mesh.P) EXPECT_NEAR(max_component(abs(p)), 1.0f, 1e-6f);  // on the cube
  for (const Vec3f& c : cube().P) EXPECT_TRUE(has_point(t.mesh, c));
  // Each face stays flat and each side of an edge gets its own face's normal.
  for (size_t k = 0; k < t.mesh.triangle_count(); ++k) {
    Vec3f n = normalize(geometric_normal(t.mesh, k));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(length(t.mesh.N[t.mesh.indices[3 * k + c]] - n), 0.0f, 1e-5f);
  }
}

// How far the limit reaches towards the cube's corner (1, 1, 1): 1/2 when smooth, 1 when sharp.
float corner_reach(const TriangleMeshData& m) {
  float reach = 0;
  for (const Vec3f& p : m.P) reach = std::max(reach, (p.x + p.y + p.z) / 3);
  return reach;
}

TEST(SubdivisionSurface, SemiSharpCreasesLieBetweenSmoothAndSharp) {
  EXPECT_NEAR(corner_reach(tessellate_subdivision_mesh(cube()).mesh), 0.5f, 1e-6f);
  float previous = 0.5f;
  for (float sharpness : {0.5f, 1.0f, 2.0f, 3.0f}) {
    SubdivisionMeshRequest r = cube();
    crease_every_cube_edge(r, sharpness);
    SubdivisionTessellation t = tessellate_subdivision_mesh(r);
    ASSERT_TRUE(t.ok()) << t.error;
    float reach = corner_reach(t.mesh);
    EXPECT_GT(reach, previous) << "sharpness " << sharpness;
    EXPECT_LT(reach, 1.0f) << "sharpness " << sharpness;
    previous = reach;
  }
}

TEST(SubdivisionSurface, CornerTagKeepsTheVertex) {
  SubdivisionMeshRequest r = cube();
  add_tag(r, "corner", {6}, {kInfiniteSharpness});
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  EXPECT_TRUE(has_point(t.mesh, {1, 1, 1}));
  EXPECT_FALSE(has_point(t.mesh, {-1, -1, -1}, 0.1f));
}

TEST(SubdivisionSurface, OpenQuadWithInterpolateBoundaryIsABilinearPatch) {
  SubdivisionMeshRequest r;
  r.scheme = "catmull-clark";
  r.P = {{0, 0, 0}, {2, 0, 0}, {2, 2, 1}, {0, 2, 0}};
  r.nvertices = {4};
  r.vertices = {0, 1, 2, 3};
  add_tag(r, "interpolateboundary", {1}, {});
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  expect_well_formed(t.mesh);
  for (const Vec3f& c : r.P) EXPECT_TRUE(has_point(t.mesh, c));
  // The boundary edges stay straight and every point is the bilinear patch's: with corners
  // and boundary fixed, the single face refines to the bilinear interpolation of its corners.
  for (const Vec3f& p : t.mesh.P) {
    float u = p.x / 2, v = p.y / 2;
    EXPECT_GE(u, -1e-6f);
    EXPECT_LE(u, 1 + 1e-6f);
    EXPECT_NEAR(p.z, u * v, 1e-5f);
  }
  for (size_t k = 0; k < t.mesh.triangle_count(); ++k) EXPECT_GT(geometric_normal(t.mesh, k).z, 0.0f);

  // "Edges only" rounds the corners: the curve of a boundary no longer reaches them.
  r.intargs = {2};
  SubdivisionTessellation rounded = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(rounded.ok());
  EXPECT_FALSE(has_point(rounded.mesh, {0, 0, 0}, 0.05f));
  // And without the tag the lone face touches the boundary: nothing is drawn, with a warning.
  r.tags.clear();
  r.nargs.clear();
  r.intargs.clear();
  SubdivisionTessellation none = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(none.ok());
  EXPECT_EQ(none.mesh.triangle_count(), 0u);
  ASSERT_EQ(none.warnings.size(), 1u);
  EXPECT_NE(none.warnings[0].find("nothing to draw"), std::string::npos);
}

TEST(SubdivisionSurface, HoleFacesVanish) {
  SubdivisionMeshRequest r = cube();
  add_tag(r, "hole", {1, 3}, {});
  SubdivisionTessellation holed = tessellate_subdivision_mesh(r);
  SubdivisionTessellation whole = tessellate_subdivision_mesh(cube());
  ASSERT_TRUE(holed.ok()) << holed.error;
  EXPECT_EQ(holed.mesh.triangle_count() * 6, whole.mesh.triangle_count() * 4);
  for (uint32_t f : holed.triangle_control_face) EXPECT_TRUE(f != 1 && f != 3);
  // The holes still shape the rest: the remaining points are points of the whole limit surface.
  for (const Vec3f& p : holed.mesh.P) EXPECT_TRUE(has_point(whole.mesh, p, 1e-6f));
  for (const Vec3f& p : holed.mesh.P) EXPECT_LT(p.z, kCubeFaceCentreLimit - 1e-3f);  // face 1 is z = 1
}

TEST(SubdivisionSurface, BilinearIsTheControlMesh) {
  SubdivisionMeshRequest r = cube();
  r.scheme = "bilinear";
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  EXPECT_EQ(t.levels, 0);
  EXPECT_EQ(t.mesh.triangle_count(), 12u);
  EXPECT_TRUE(t.mesh.N.empty());
  EXPECT_EQ(t.mesh.P, r.P);
  for (size_t k = 0; k < 12; ++k) EXPECT_GT(dot(geometric_normal(t.mesh, k), t.mesh.P[t.mesh.indices[3 * k]]), 0.0f);
}

// Vertex-class st is subdivided by the rules that move P, which reproduce affine functions: st
// given as an affine map of P is that map of the limit position at every emitted vertex,
// on a mesh with extraordinary vertices and a crease.
TEST(SubdivisionSurface, VertexStIsSubdividedLikeP) {
  SubdivisionMeshRequest r = pentagon_beside_a_triangle();
  add_tag(r, "crease", {2, 3}, {1.5f});
  auto st_of = [](const Vec3f& p) { return Vec2f{0.25f * p.x + 0.1f * p.y + 0.5f, -0.2f * p.y + 0.05f * p.x}; };
  for (const Vec3f& p : r.P) r.vertex_st.push_back(st_of(p));
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  ASSERT_EQ(t.mesh.uv.size(), t.mesh.P.size());
  for (size_t i = 0; i < t.mesh.P.size(); ++i) {
    EXPECT_NEAR(t.mesh.uv[i].x, st_of(t.mesh.P[i]).x, 1e-5f);
    EXPECT_NEAR(t.mesh.uv[i].y, st_of(t.mesh.P[i]).y, 1e-5f);
  }
  // No seams: the vertices are those of the mesh without st.
  r.vertex_st.clear();
  EXPECT_EQ(tessellate_subdivision_mesh(r).mesh.P.size(), t.mesh.P.size());
}

// Per-corner st is refined linearly inside each face: on a grid whose corners carry the face's
// own copy of a map, every triangle's st lies in its face's square of the map, a vertex where two
// faces' values differ (a seam) is emitted once per value, and with one value per vertex (no
// seam) the vertices are those of the mesh without st.
TEST(SubdivisionSurface, CornerStIsLinearInsideEachFaceAndSplitsSeams) {
  SubdivisionMeshRequest r = planar_grid(2);
  add_tag(r, "interpolateboundary", {}, {});
  const size_t plain_vertices = tessellate_subdivision_mesh(r).mesh.P.size();
  // Face f's corners get (f + x - i, y - j): each face its own unit square of s, 10 apart.
  for (size_t f = 0, c = 0; f < r.nvertices.size(); ++f) {
    const int i = int(f) % 2, j = int(f) / 2;
    for (int k = 0; k < 4; ++k, ++c) {
      const Vec3f& p = r.P[size_t(r.vertices[c])];
      r.corner_st.push_back({10.0f * float(f) + p.x - float(i), p.y - float(j)});
    }
  }
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  ASSERT_EQ(t.mesh.uv.size(), t.mesh.P.size());
  for (size_t k = 0; k < t.mesh.triangle_count(); ++k) {
    const float base = 10.0f * float(t.triangle_control_face[k]);
    for (int c = 0; c < 3; ++c) {
      const Vec2f st = t.mesh.uv[t.mesh.indices[3 * k + c]];
      EXPECT_GE(st.x, base - 1e-6f);
      EXPECT_LE(st.x, base + 1.0f + 1e-6f);
      EXPECT_GE(st.y, -1e-6f);
      EXPECT_LE(st.y, 1.0f + 1e-6f);
    }
  }
  // The vertices on the edges between faces are emitted once per face (the centre once for each
  // of its four): more vertices than without st.
  EXPECT_GT(t.mesh.P.size(), plain_vertices);
  // The linear rule: a face's centre (the face point, a smooth vertex after refinement) keeps
  // st (base + 0.5, 0.5) exactly.
  bool centre_found = false;
  for (size_t i = 0; i < t.mesh.P.size(); ++i) {
    if (std::abs(t.mesh.uv[i].x - 0.5f) < 1e-6f && std::abs(t.mesh.uv[i].y - 0.5f) < 1e-6f) centre_found = true;
  }
  EXPECT_TRUE(centre_found);

  r.corner_st.clear();
  for (size_t c = 0; c < r.vertices.size(); ++c) {
    const Vec3f& p = r.P[size_t(r.vertices[c])];
    r.corner_st.push_back({p.x, p.y});
  }
  SubdivisionTessellation seamless = tessellate_subdivision_mesh(r);
  EXPECT_EQ(seamless.mesh.P.size(), plain_vertices);
}

// "bilinear" keeps the control faces: per-corner st is each face's own corners exactly.
TEST(SubdivisionSurface, BilinearCornerStIsTheCornersValues) {
  SubdivisionMeshRequest r = cube();
  r.scheme = "bilinear";
  for (size_t c = 0; c < r.vertices.size(); ++c) r.corner_st.push_back({float(c), float(c % 4)});
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  ASSERT_EQ(t.mesh.uv.size(), t.mesh.P.size());
  EXPECT_EQ(t.mesh.P.size(), 24u);  // one vertex per corner
  for (size_t k = 0; k < t.mesh.triangle_count(); ++k) {
    const uint32_t f = t.triangle_control_face[k];
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = t.mesh.indices[3 * k + c];
      const size_t corner = size_t(t.mesh.uv[v].x);
      EXPECT_EQ(corner / 4, f);                                   // a corner of its own face
      EXPECT_EQ(t.mesh.P[v], r.P[size_t(r.vertices[corner])]);  // at that corner's point
    }
  }
}

TEST(SubdivisionSurface, LoopIsRefinedAsCatmullClarkWithAWarning) {
  SubdivisionMeshRequest r = cube();
  r.scheme = "loop";
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_NE(t.warnings[0].find("loop"), std::string::npos);
  EXPECT_EQ(t.mesh.P, tessellate_subdivision_mesh(cube()).mesh.P);
}

TEST(SubdivisionSurface, UnknownTagsWarnAndNargsOfTwoPerTagAreRead) {
  SubdivisionMeshRequest r = cube();
  r.tags = {"sparkle", "corner"};
  r.nargs = {1, 0, 1, 1};  // RI 3.2: integers and floats per tag
  r.intargs = {7, 6};
  r.floatargs = {kInfiniteSharpness};
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_NE(t.warnings[0].find("unknown tag \"sparkle\""), std::string::npos);
  EXPECT_TRUE(has_point(t.mesh, {1, 1, 1}));
}

TEST(SubdivisionSurface, LevelsFitTheTriangleBudget) {
  EXPECT_EQ(subdivision_levels_for(24), kMaxSubdivisionLevels);
  for (size_t corners : {size_t(1000), size_t(100000), size_t(10000000)}) {
    int levels = subdivision_levels_for(corners);
    EXPECT_GE(levels, 1);
    if (levels > 1) {
      EXPECT_LE(2 * corners << (2 * (levels - 1)), kSubdivisionTriangleBudget);
    }
    if (levels < kMaxSubdivisionLevels) {
      EXPECT_GT(2 * corners << (2 * levels), kSubdivisionTriangleBudget);
    }
  }
}

// The error names what is wrong; the mesh is empty.
std::string error_of(const SubdivisionMeshRequest& r) {
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  EXPECT_TRUE(t.mesh.P.empty());
  return t.error;
}

TEST(SubdivisionSurface, BadInputIsAnError) {
  auto with = [](auto change) {
    SubdivisionMeshRequest r = cube();
    change(r);
    return error_of(r);
  };
  EXPECT_NE(with([](auto& r) { r.scheme = "doo-sabin"; }).find("unknown subdivision scheme"), std::string::npos);
  EXPECT_NE(with([](auto& r) { r.nvertices.clear(); }).find("no faces"), std::string::npos);
  EXPECT_NE(with([](auto& r) { r.nvertices[0] = 5; }).find("adds up to"), std::string::npos);
  EXPECT_NE(with([](auto& r) { r.nvertices[0] = 2; }).find("at least 3"), std::string::npos);
  EXPECT_NE(with([](auto& r) { r.vertices[3] = 8; }).find("out of range"), std::string::npos);
  EXPECT_NE(with([](auto& r) { r.vertices[3] = -1; }).find("out of range"), std::string::npos);
  EXPECT_NE(with([](auto& r) { r.vertices[3] = 0; }).find("twice"), std::string::npos);
  EXPECT_NE(with([](auto& r) { r.P[2].y = NAN; }).find("non-finite"), std::string::npos);
  EXPECT_NE(with([](auto& r) { std::reverse(r.vertices.begin(), r.vertices.begin() + 4); }).find("consistently"),
            std::string::npos);
  EXPECT_NE(with([](auto& r) {
              r.nvertices.push_back(3);  // a third face on edge (0, 1)
              r.vertices.insert(r.vertices.end(), {1, 0, 2});
            }).find("more than two faces"),
            std::string::npos);
  EXPECT_NE(with([](auto& r) { add_tag(r, "crease", {0}, {1}); }).find("chain of at least 2"), std::string::npos);
  EXPECT_NE(with([](auto& r) { add_tag(r, "crease", {0, 1}, {-1}); }).find("sharpness"), std::string::npos);
  EXPECT_NE(with([](auto& r) { add_tag(r, "corner", {9}, {1}); }).find("out of range"), std::string::npos);
  EXPECT_NE(with([](auto& r) { add_tag(r, "hole", {6}, {}); }).find("out of range"), std::string::npos);
  EXPECT_NE(with([](auto& r) { add_tag(r, "hole", {1}, {2}); }).find("no floats"), std::string::npos);
  EXPECT_NE(with([](auto& r) { add_tag(r, "interpolateboundary", {3}, {}); }).find("mode 3"), std::string::npos);
  EXPECT_NE(with([](auto& r) {
              add_tag(r, "hole", {1}, {});
              r.nargs.push_back(0);
            }).find("nargs has 4 values for 1 tags"),
            std::string::npos);
  EXPECT_NE(with([](auto& r) {
              add_tag(r, "hole", {1}, {});
              r.nargs[0] = 3;
            }).find("run past the end"),
            std::string::npos);
  EXPECT_NE(with([](auto& r) {
              add_tag(r, "hole", {1}, {});
              r.intargs.push_back(2);
            }).find("nargs uses"),
            std::string::npos);
}

TEST(SubdivisionSurface, BowtieVertexIsAnError) {
  // Two triangles that share only vertex 0.
  SubdivisionMeshRequest r;
  r.scheme = "catmull-clark";
  r.P = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  r.nvertices = {3, 3};
  r.vertices = {0, 1, 2, 0, 3, 4};
  EXPECT_NE(error_of(r).find("vertex 0"), std::string::npos);
}

TEST(SubdivisionSurface, CreaseOnANonEdgeWarns) {
  SubdivisionMeshRequest r = cube();
  add_tag(r, "crease", {0, 6}, {2});
  SubdivisionTessellation t = tessellate_subdivision_mesh(r);
  ASSERT_TRUE(t.ok()) << t.error;
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_NE(t.warnings[0].find("(0, 6) is not an edge"), std::string::npos);
}

}  // namespace
}  // namespace darc
