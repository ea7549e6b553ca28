// Patch and PatchMesh tessellation against analytic surfaces: bilinear areas, a plane and a
// cylinder section from bicubic patches, a B-spline mesh of a uniform grid (linear precision), a
// periodic tube that closes, shared vertices between patches, winding, counts and bad input.
#include "core/geometry/surfaces/patches/patch_tessellation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

#include "support/triangle_mesh_checks.h"

namespace darc {
namespace {

using test::boundary_edges;
using test::max_normal_turn;
using test::mesh_area;
using test::non_manifold_edges;
using test::well_formed;
using test::wound_against_normals;

constexpr float kOnSurface = 2e-6f;   // float positions of O(1) coordinates
constexpr float kUnitNormal = 1e-5f;  // float normals from double derivatives

CurveBasis basis(const char* name) { return standard_basis(name).value_or(bezier_basis()); }

PatchMeshDescription bilinear(std::vector<Vec3d> corners) {
  PatchMeshDescription m;
  m.nu = m.nv = 2;
  for (const Vec3d& c : corners) m.points.push_back({c, 1});
  return m;
}

PatchMeshDescription bicubic(const char* basis_name, int nu, int nv, const std::vector<HomogeneousPoint>& points) {
  PatchMeshDescription m;
  m.type = PatchType::bicubic;
  m.nu = nu;
  m.nv = nv;
  m.u_basis = m.v_basis = basis(basis_name);
  m.points = points;
  return m;
}

TriangleMeshData tessellate(const PatchMeshDescription& m) {
  std::string error;
  TriangleMeshData mesh = tessellate_patch_mesh(m, error);
  EXPECT_EQ(error, "");
  EXPECT_TRUE(well_formed(mesh));
  return mesh;
}

std::string error_of(const PatchMeshDescription& m) {
  std::string error;
  TriangleMeshData mesh = tessellate_patch_mesh(m, error);
  EXPECT_EQ(mesh.triangle_count(), 0u);
  return error;
}

TEST(PatchTessellation, PlanarBilinearPatchHasTheTrapezoidArea) {
  // RI corner order (0,0), (1,0), (0,1), (1,1): parallel sides 2 and 1, height 1.
  TriangleMeshData mesh = tessellate(bilinear({{0, 0, 0}, {2, 0, 0}, {0.5, 1, 0}, {1.5, 1, 0}}));
  EXPECT_NEAR(mesh_area(mesh), 1.5, 1e-6);
  EXPECT_EQ(mesh.triangle_count(), 2u);  // flat: nothing to refine
  for (Vec3f n : mesh.N) EXPECT_NEAR(n.z, 1, kUnitNormal);
}

TEST(PatchTessellation, SaddleBilinearPatchHasTheIntegratedArea) {
  // P(u, v) = (u, v, uv): |dP/du x dP/dv| = sqrt(1 + u^2 + v^2), integrated by Simpson's rule.
  TriangleMeshData mesh = tessellate(bilinear({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}));
  constexpr int kSteps = 200;  // Simpson on a smooth integrand: error ~1e-10
  double area = 0;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j) {
      const double wi = (i == 0 || i == kSteps) ? 1 : (i % 2 ? 4 : 2),
                   wj = (j == 0 || j == kSteps) ? 1 : (j % 2 ? 4 : 2);
      const double u = double(i) / kSteps, v = double(j) / kSteps;
      area += wi * wj * std::sqrt(1 + u * u + v * v);
    }
  area /= 9.0 * kSteps * kSteps;
  EXPECT_NEAR(mesh_area(mesh), area, 1e-3 * area);  // flat triangles under a curved surface
  EXPECT_GT(mesh.triangle_count(), 2u);             // the twist asks for refinement
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    const Vec3f p = mesh.P[i];
    EXPECT_NEAR(p.z, p.x * p.y, kOnSurface);
    EXPECT_NEAR(p.x, mesh.uv[i].x, kOnSurface);  // P = (u, v, uv)
    EXPECT_NEAR(p.y, mesh.uv[i].y, kOnSurface);
    // The exact normal of z = xy is (-y, -x, 1) / |.|.
    const Vec3f exact = normalize(Vec3f{-p.y, -p.x, 1});
    EXPECT_NEAR(dot(mesh.N[i], exact), 1, kUnitNormal);
  }
  EXPECT_EQ(wound_against_normals(mesh), 0);
}

TEST(PatchTessellation, WindingFollowsDPduCrossDPdv) {
  // u along +x, v along +y: dP/du x dP/dv = +z; exchanging the two middle corners swaps u and v.
  TriangleMeshData up = tessellate(bilinear({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
  TriangleMeshData down = tessellate(bilinear({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}));
  for (const auto& [mesh, z] : {std::pair{&up, 1.0}, std::pair{&down, -1.0}}) {
    ASSERT_EQ(mesh->triangle_count(), 2u);
    for (size_t t = 0; t < mesh->indices.size(); t += 3) {
      const Vec3f a = mesh->P[mesh->indices[t]], b = mesh->P[mesh->indices[t + 1]], c = mesh->P[mesh->indices[t + 2]];
      EXPECT_NEAR(normalize(cross(b - a, c - a)).z, z, kUnitNormal);
    }
    for (Vec3f n : mesh->N) EXPECT_NEAR(n.z, z, kUnitNormal);
  }
}

TEST(PatchTessellation, BicubicBezierPatchOnAPlaneStaysOnIt) {
  // Control points at uneven in-plane positions on z = 1 + 0.3 x - 0.2 y.
  std::vector<HomogeneousPoint> points;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const double x = i + 0.3 * std::sin(1.7 * i + j), y = j + 0.25 * std::cos(i - 2.1 * j);
      points.push_back({{x, y, 1 + 0.3 * x - 0.2 * y}, 1});
    }
  TriangleMeshData mesh = tessellate(bicubic("bezier", 4, 4, points));
  const Vec3f plane = normalize(Vec3f{-0.3f, 0.2f, 1});
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    const Vec3f p = mesh.P[i];
    EXPECT_NEAR(p.z, 1 + 0.3f * p.x - 0.2f * p.y, 4 * kOnSurface);
    EXPECT_NEAR(dot(mesh.N[i], plane), 1, kUnitNormal);
  }
  // Corners interpolate the control net's corners (Bézier).
  EXPECT_NEAR(mesh.P.front().x, points.front().xyz.x, kOnSurface);
  EXPECT_NEAR(mesh.P.back().y, points.back().xyz.y, kOnSurface);
}

// A quarter of the unit cylinder, x^2 + y^2 = 1 from (1, 0) to (0, 1), z from 0 to height: the
// rational quadratic arc (weights 1, sqrt(1/2), 1) raised to a cubic, in homogeneous "Pw" form.
std::vector<HomogeneousPoint> quarter_cylinder(double height) {
  const double w = std::sqrt(0.5);
  const HomogeneousPoint h0{{1, 0, 0}, 1}, h1{{w, w, 0}, w}, h2{{0, 1, 0}, 1};
  auto blend = [](const HomogeneousPoint& a, double wa, const HomogeneousPoint& b, double wb) {
    return HomogeneousPoint{a.xyz * wa + b.xyz * wb, a.w * wa + b.w * wb};
  };
  const HomogeneousPoint arc[4] = {h0, blend(h0, 1.0 / 3, h1, 2.0 / 3), blend(h1, 2.0 / 3, h2, 1.0 / 3), h2};
  std::vector<HomogeneousPoint> points;
  for (int j = 0; j < 4; ++j)
    for (const HomogeneousPoint& a : arc) points.push_back({{a.xyz.x, a.xyz.y, a.w * height * j / 3}, a.w});
  return points;
}

TEST(PatchTessellation, RationalBicubicPatchIsACylinderSection) {
  TriangleMeshData mesh = tessellate(bicubic("bezier", 4, 4, quarter_cylinder(2)));
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    const Vec3f p = mesh.P[i], n = mesh.N[i];
    EXPECT_NEAR(std::hypot(p.x, p.y), 1, kOnSurface);
    EXPECT_GE(p.z, -kOnSurface);
    EXPECT_LE(p.z, 2 + kOnSurface);
    // Outward and radial: dP/du runs counter-clockwise, dP/dv up.
    EXPECT_NEAR(n.x, p.x, kUnitNormal);
    EXPECT_NEAR(n.y, p.y, kUnitNormal);
    EXPECT_NEAR(n.z, 0, kUnitNormal);
  }
  // The density rules: chords within kMaxDeviationFraction of the patch size (its diagonal is
  // sqrt(2 + 4)), adjacent normals within kMaxNormalTurn (probes estimate it to a few percent).
  double worst_chord = 1;
  for (size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const Vec3f mid = (mesh.P[mesh.indices[t + e]] + mesh.P[mesh.indices[t + (e + 1) % 3]]) * 0.5f;
      worst_chord = std::min(worst_chord, double(std::hypot(mid.x, mid.y)));
    }
  EXPECT_GT(worst_chord, 1 - kMaxDeviationFraction * std::sqrt(6.0));
  EXPECT_LT(max_normal_turn(mesh), 1.1 * kMaxNormalTurn);
  EXPECT_GT(max_normal_turn(mesh), 0.5 * kMaxNormalTurn);  // and not far finer than asked
  EXPECT_NEAR(mesh_area(mesh), M_PI, M_PI * 2e-3);         // a quarter of 2 pi r h, r = 1, h = 2
}

// nu x nv points on the integer grid (i, j, 0).
std::vector<HomogeneousPoint> integer_grid(int nu, int nv) {
  std::vector<HomogeneousPoint> points;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) points.push_back({{double(i), double(j), 0}, 1});
  return points;
}

TEST(PatchTessellation, BSplineMeshOfAUniformGridIsThePlane) {
  // 6 x 5 points, step 1: 3 x 2 patches; a uniform B-spline reproduces a linear function, so
  // the surface is (1 + 3u, 1 + 2v, 0) over the mesh's (u, v) in [0, 1]^2.
  TriangleMeshData mesh = tessellate(bicubic("b-spline", 6, 5, integer_grid(6, 5)));
  float umin = 1, umax = 0, vmin = 1, vmax = 0;
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    const Vec3f p = mesh.P[i];
    const Vec2f uv = mesh.uv[i];
    EXPECT_NEAR(p.z, 0, kOnSurface);
    EXPECT_NEAR(p.x, 1 + 3 * uv.x, 4 * kOnSurface);
    EXPECT_NEAR(p.y, 1 + 2 * uv.y, 4 * kOnSurface);
    EXPECT_NEAR(mesh.N[i].z, 1, kUnitNormal);
    umin = std::min(umin, uv.x), umax = std::max(umax, uv.x), vmin = std::min(vmin, uv.y), vmax = std::max(vmax, uv.y);
  }
  EXPECT_EQ(umin, 0);
  EXPECT_EQ(umax, 1);
  EXPECT_EQ(vmin, 0);
  EXPECT_EQ(vmax, 1);
  EXPECT_NEAR(mesh_area(mesh), 3 * 2, 1e-5);
}

TEST(PatchTessellation, PeriodicMeshClosesUponItself) {
  // 8 B-spline points around the unit circle in u (periodic: 8 patches), 4 rings up z (one patch).
  constexpr int kAround = 8;
  std::vector<HomogeneousPoint> points;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < kAround; ++i) {
      const double a = 2 * M_PI * i / kAround;
      points.push_back({{std::cos(a), std::sin(a), double(j)}, 1});
    }
  PatchMeshDescription m = bicubic("b-spline", kAround, 4, points);
  m.u_periodic = true;
  TriangleMeshData mesh = tessellate(m);
  // A tube: its only borders are the rings at v = 0 and v = 1, as many edges each as there are
  // vertices around (which the last column does not repeat).
  std::set<std::tuple<float, float, float>> distinct;
  for (Vec3f p : mesh.P) distinct.insert({p.x, p.y, p.z});
  EXPECT_EQ(distinct.size(), mesh.P.size());
  size_t around = 0;
  for (Vec2f uv : mesh.uv) around += uv.y == 0;
  EXPECT_GE(around, size_t(3 * kAround));  // a circle needs several segments per patch
  EXPECT_EQ(boundary_edges(mesh), int(2 * around));
  EXPECT_EQ(non_manifold_edges(mesh), 0);
  EXPECT_EQ(wound_against_normals(mesh), 0);
  for (size_t i = 0; i < mesh.P.size(); ++i)  // outward (counter-clockwise u, v up)
    EXPECT_GT(mesh.N[i].x * mesh.P[i].x + mesh.N[i].y * mesh.P[i].y, 0.99f * std::hypot(mesh.P[i].x, mesh.P[i].y));
}

TEST(PatchTessellation, AdjacentPatchesShareTheirEdgeVertices) {
  // A Bézier mesh of 2 x 1 patches: the left one flat, the right one bulging, so they ask for
  // different densities; the shared column must still be one line of shared vertices.
  std::vector<HomogeneousPoint> points = integer_grid(7, 4);
  for (HomogeneousPoint& p : points)
    if (p.xyz.x > 3) p.xyz.z = 2 * std::sin(p.xyz.x) * std::cos(p.xyz.y);
  TriangleMeshData mesh = tessellate(bicubic("bezier", 7, 4, points));
  size_t columns = 0, rows = 0;  // vertices along v = 0 and along u = 0
  for (Vec2f uv : mesh.uv) columns += uv.y == 0, rows += uv.x == 0;
  // One rectangle of cells: its border only, no crack inside.
  EXPECT_EQ(boundary_edges(mesh), int(2 * (columns - 1) + 2 * (rows - 1)));
  EXPECT_EQ(non_manifold_edges(mesh), 0);
  EXPECT_EQ(mesh.P.size(), columns * rows);
  EXPECT_EQ(wound_against_normals(mesh), 0);
}

TEST(PatchTessellation, CountsFollowTheBasisStepAndWrap) {
  std::string error;
  auto counts = [&](PatchType type, const char* name, int nu, bool periodic) {
    PatchMeshDescription m;
    m.type = type;
    m.u_basis = m.v_basis = basis(name);
    m.nu = nu;
    m.nv = type == PatchType::bicubic ? 4 : 2;
    m.u_periodic = periodic;
    std::optional<PatchCounts> c = patch_counts(m, error);
    EXPECT_EQ(error, "") << name << " " << nu;
    return c ? c->nupatches : -1;
  };
  EXPECT_EQ(counts(PatchType::bilinear, "bezier", 5, false), 4);
  EXPECT_EQ(counts(PatchType::bilinear, "bezier", 5, true), 5);
  EXPECT_EQ(counts(PatchType::bicubic, "bezier", 10, false), 3);
  EXPECT_EQ(counts(PatchType::bicubic, "bezier", 9, true), 3);
  EXPECT_EQ(counts(PatchType::bicubic, "b-spline", 7, false), 4);
  EXPECT_EQ(counts(PatchType::bicubic, "b-spline", 7, true), 7);
  EXPECT_EQ(counts(PatchType::bicubic, "catmull-rom", 6, false), 3);
  EXPECT_EQ(counts(PatchType::bicubic, "hermite", 6, false), 2);
  EXPECT_EQ(counts(PatchType::bicubic, "power", 8, true), 2);
  PatchMeshDescription m = bicubic("b-spline", 7, 4, {});
  m.u_periodic = true;
  const PatchCounts c{7, 1};
  EXPECT_EQ(uniform_count(c), 7u);
  EXPECT_EQ(varying_count(m, c), 7u * 2u);  // the periodic direction's corners wrap
}

TEST(PatchTessellation, BadInputIsAnErrorNamingTheProblem) {
  EXPECT_NE(error_of(bicubic("bezier", 5, 4, integer_grid(5, 4))).find("4 + 3 k"), std::string::npos);
  EXPECT_NE(error_of(bicubic("bezier", 4, 4, integer_grid(4, 3))).find("needs 16 points, found 12"), std::string::npos);
  PatchMeshDescription periodic = bicubic("bezier", 4, 4, integer_grid(4, 4));
  periodic.v_periodic = true;  // 4 is not a multiple of the step 3
  EXPECT_NE(error_of(periodic).find("periodic bicubic"), std::string::npos);
  PatchMeshDescription one = bilinear({{0, 0, 0}, {1, 0, 0}});
  one.nu = 1;
  EXPECT_NE(error_of(one).find("nu >= 2"), std::string::npos);
  PatchMeshDescription zero_step = bicubic("bezier", 4, 4, integer_grid(4, 4));
  zero_step.u_basis.step = 0;
  EXPECT_NE(error_of(zero_step).find("step must be at least 1"), std::string::npos);
  PatchMeshDescription weightless = bilinear({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
  weightless.points[2].w = 0;
  EXPECT_NE(error_of(weightless).find("point 2 has weight w = 0"), std::string::npos);
  PatchMeshDescription nan = bilinear({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}, {1, 1, 0}});
  EXPECT_NE(error_of(nan).find("point 2 is not finite"), std::string::npos);
  PatchMeshDescription wrapped_heights = bilinear({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 3}});
  wrapped_heights.height_field = wrapped_heights.u_periodic = true;
  EXPECT_NE(error_of(wrapped_heights).find("cannot be periodic"), std::string::npos);
}

TEST(PatchTessellation, HeightFieldTakesXAndYFromTheParameters) {
  // "Pz": heights 0, 1, 2, 3 at the corners: z = u + 2v over x = u, y = v.
  PatchMeshDescription m = bilinear({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 3}});
  m.height_field = true;
  TriangleMeshData mesh = tessellate(m);
  const Vec3f plane = normalize(Vec3f{-1, -2, 1});
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    EXPECT_EQ(mesh.P[i].x, mesh.uv[i].x);
    EXPECT_EQ(mesh.P[i].y, mesh.uv[i].y);
    EXPECT_NEAR(mesh.P[i].z, mesh.P[i].x + 2 * mesh.P[i].y, kOnSurface);
    EXPECT_NEAR(dot(mesh.N[i], plane), 1, kUnitNormal);
  }
  EXPECT_NEAR(mesh_area(mesh), std::sqrt(6.0), 1e-5);  // |(1, 0, 1) x (0, 1, 2)|
}

TEST(PatchTessellation, WildControlNetIsCappedPerPatch) {
  std::vector<HomogeneousPoint> points = integer_grid(4, 4);
  for (size_t k = 0; k < points.size(); ++k) points[k].xyz.z = (k % 2 ? 1e6 : -1e6);
  TriangleMeshData mesh = tessellate(bicubic("bezier", 4, 4, points));
  EXPECT_LE(mesh.triangle_count(), size_t(2 * kMaxSegmentsPerSpan * kMaxSegmentsPerSpan));
}

TEST(PatchTessellation, CollapsedEdgeGetsTheNormalOfItsNeighbourhood) {
  // A bilinear triangle: the v = 1 edge collapsed to one point (dP/du = 0 there). The surface is
  // the z = 0 plane, so every normal must still be +z, never zero or NaN.
  TriangleMeshData mesh = tessellate(bilinear({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 1, 0}}));
  for (Vec3f n : mesh.N) EXPECT_NEAR(n.z, 1, kUnitNormal);
  EXPECT_NEAR(mesh_area(mesh), 0.5, 1e-6);
}

}  // namespace
}  // namespace darc
