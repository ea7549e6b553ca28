// NuPatch evaluation and tessellation against exact surfaces: a clamped cubic equals its Bézier
// form, Greville points reproduce the plane's parameters over non-uniform knots, rational
// quadratic arcs give a cylinder and a sphere on the exact radius with radial normals, the
// [min, max] range, winding, and validation.
#include "core/geometry/surfaces/patches/nurbs_tessellation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/math/curve_basis.h"
#include "support/triangle_mesh_checks.h"

namespace darc {
namespace {

using test::max_normal_turn;
using test::mesh_area;
using test::well_formed;
using test::wound_against_normals;

constexpr double kExact = 1e-12;
constexpr float kOnSurface = 2e-6f;
constexpr float kUnitNormal = 1e-5f;
constexpr double kDerivativeStep = 1e-6;       // central differences
constexpr double kDerivativeTolerance = 1e-6;  // O(step^2) plus rounding over the step

TriangleMeshData tessellate(const NurbsSurfaceDescription& s) {
  std::string error;
  TriangleMeshData mesh = tessellate_nurbs(s, error);
  EXPECT_EQ(error, "");
  EXPECT_TRUE(well_formed(mesh));
  return mesh;
}

std::string error_of(const NurbsSurfaceDescription& s) {
  std::string error;
  EXPECT_FALSE(validate_nurbs(s, error));
  EXPECT_EQ(tessellate_nurbs(s, error).triangle_count(), 0u);
  return error;
}

// The unit circle as 9 rational quadratic control points (x, y, w) in four 90-degree arcs,
// knots 0 0 0 1 1 2 2 3 3 4 4 4: u = 1, 2, 3 are at 90, 180, 270 degrees.
struct RationalArc {
  std::vector<double> x, y, w, knots;
};
RationalArc full_circle() {
  const double h = std::sqrt(0.5);
  return {{1, 1, 0, -1, -1, -1, 0, 1, 1},
          {0, 1, 1, 1, 0, -1, -1, -1, 0},
          {1, h, 1, h, 1, h, 1, h, 1},
          {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}};
}
// The half circle from the south pole to the north pole in the (r, z) plane: r = x, z = y.
RationalArc half_circle() {
  const double h = std::sqrt(0.5);
  return {{0, 1, 1, 1, 0}, {-1, -1, 0, 1, 1}, {1, h, 1, h, 1}, {0, 0, 0, 1, 1, 2, 2, 2}};
}

NurbsSurfaceDescription sphere() {
  const RationalArc around = full_circle(), profile = half_circle();
  NurbsSurfaceDescription s;
  s.u = {9, 3, around.knots, 0, 4};
  s.v = {5, 3, profile.knots, 0, 2};
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 9; ++i) {
      const double w = around.w[size_t(i)] * profile.w[size_t(j)];
      const Vec3d p{around.x[size_t(i)] * profile.x[size_t(j)], around.y[size_t(i)] * profile.x[size_t(j)],
                    profile.y[size_t(j)]};
      s.points.push_back({p * w, w});  // "Pw" is homogeneous: (x w, y w, z w, w)
    }
  return s;
}

NurbsSurfaceDescription cylinder(double height) {
  const RationalArc around = full_circle();
  NurbsSurfaceDescription s;
  s.u = {9, 3, around.knots, 0, 4};
  s.v = {2, 2, {0, 0, 1, 1}, 0, 1};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 9; ++i) {
      const double w = around.w[size_t(i)];
      s.points.push_back({Vec3d{around.x[size_t(i)], around.y[size_t(i)], height * j} * w, w});
    }
  return s;
}

TEST(NurbsTessellation, ClampedCubicEqualsItsBezierForm) {
  NurbsSurfaceDescription s;
  s.u = s.v = {4, 4, {0, 0, 0, 0, 1, 1, 1, 1}, 0, 1};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) s.points.push_back({{i + 0.2 * j, j - 0.1 * i * i, std::sin(i + 2.0 * j)}, 1});
  for (double u : {0.0, 0.3, 0.77, 1.0})
    for (double v : {0.0, 0.45, 1.0}) {
      // Bézier in u per row, then in v.
      Vec3d rows[4];
      for (int j = 0; j < 4; ++j) {
        Vec3d cp[4];
        for (int i = 0; i < 4; ++i) cp[i] = s.points[size_t(i + 4 * j)].xyz;
        rows[j] = bezier_evaluate(cp, float(u));
      }
      const Vec3d expected = bezier_evaluate(rows, float(v));
      const SurfaceSample got = evaluate_nurbs(s, u, v);
      EXPECT_NEAR(got.P.x, expected.x, 1e-6);  // bezier_evaluate takes a float parameter
      EXPECT_NEAR(got.P.y, expected.y, 1e-6);
      EXPECT_NEAR(got.P.z, expected.z, 1e-6);
    }
}

TEST(NurbsTessellation, DerivativesMatchCentralDifferences) {
  NurbsSurfaceDescription s = sphere();
  for (double u : {0.3, 1.5, 2.9, 3.7})
    for (double v : {0.4, 1.0, 1.6}) {
      const SurfaceSample c = evaluate_nurbs(s, u, v);
      const Vec3d du = (evaluate_nurbs(s, u + kDerivativeStep, v).P - evaluate_nurbs(s, u - kDerivativeStep, v).P) /
                       (2 * kDerivativeStep);
      const Vec3d dv = (evaluate_nurbs(s, u, v + kDerivativeStep).P - evaluate_nurbs(s, u, v - kDerivativeStep).P) /
                       (2 * kDerivativeStep);
      EXPECT_LT(length(c.dPdu - du), kDerivativeTolerance) << u << " " << v;
      EXPECT_LT(length(c.dPdv - dv), kDerivativeTolerance) << u << " " << v;
    }
}

TEST(NurbsTessellation, GrevillePointsReproduceTheParametersOverNonUniformKnots) {
  // A B-spline whose control points sit at the Greville abscissae (the mean of the `degree`
  // knots after each) is the identity: P(u, v) = (u, v, 0), for any knots.
  NurbsSurfaceDescription s;
  s.u = {6, 4, {0, 0, 0, 0, 0.3, 1.1, 2, 2, 2, 2}, 0, 2};
  s.v = {4, 3, {-1, -1, -1, 0.5, 3, 3, 3}, -1, 3};
  auto greville = [](const NurbsDirection& d, int i) {
    double sum = 0;
    for (int k = 1; k < d.order; ++k) sum += d.knots[size_t(i + k)];
    return sum / (d.order - 1);
  };
  for (int j = 0; j < s.v.n; ++j)
    for (int i = 0; i < s.u.n; ++i) s.points.push_back({{greville(s.u, i), greville(s.v, j), 0}, 1});
  for (double u : {0.0, 0.2, 0.3, 0.9, 1.5, 2.0})
    for (double v : {-1.0, 0.0, 0.5, 2.2, 3.0}) {
      const SurfaceSample p = evaluate_nurbs(s, u, v);
      EXPECT_NEAR(p.P.x, u, kExact * 100);
      EXPECT_NEAR(p.P.y, v, kExact * 100);
      EXPECT_NEAR(length(p.dPdu - Vec3d{1, 0, 0}), 0, kExact * 100);
      EXPECT_NEAR(length(p.dPdv - Vec3d{0, 1, 0}), 0, kExact * 100);
    }
  TriangleMeshData mesh = tessellate(s);
  EXPECT_EQ(mesh.triangle_count(), 2u * 3 * 2);  // flat: one cell per knot interval (3 x 2)
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    EXPECT_NEAR(mesh.P[i].x, mesh.uv[i].x, kOnSurface);
    EXPECT_NEAR(mesh.P[i].y, mesh.uv[i].y, kOnSurface);
  }
  EXPECT_NEAR(mesh_area(mesh), 2 * 4, 1e-5);
}

TEST(NurbsTessellation, SphereVerticesLieOnTheRadiusWithRadialNormals) {
  TriangleMeshData mesh = tessellate(sphere());
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    const Vec3f p = mesh.P[i];
    EXPECT_NEAR(length(p), 1, kOnSurface);
    // Outward: u runs counter-clockwise about z, v from the south pole to the north pole. At the
    // poles the normal comes from just inside the span (kDegenerateNudge): within 1e-3.
    EXPECT_NEAR(dot(mesh.N[i], p), 1, 1e-3f) << p.x << " " << p.y << " " << p.z;
  }
  EXPECT_EQ(wound_against_normals(mesh), 0);
  EXPECT_LT(max_normal_turn(mesh), 1.1 * kMaxNormalTurn);
  EXPECT_NEAR(mesh_area(mesh), 4 * M_PI, 4 * M_PI * 2e-3);
}

TEST(NurbsTessellation, SphereSeamVerticesCoincide) {
  // u = 0 and u = 4 are the same meridian: its vertices are at the same places from both sides.
  TriangleMeshData mesh = tessellate(sphere());
  std::vector<std::pair<float, Vec3f>> first, last;
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    if (mesh.uv[i].x == 0) first.push_back({mesh.uv[i].y, mesh.P[i]});
    if (mesh.uv[i].x == 4) last.push_back({mesh.uv[i].y, mesh.P[i]});
  }
  ASSERT_EQ(first.size(), last.size());
  ASSERT_GT(first.size(), 2u);
  for (size_t k = 0; k < first.size(); ++k) {
    EXPECT_EQ(first[k].first, last[k].first);
    EXPECT_LT(length(first[k].second - last[k].second), kOnSurface);
  }
}

TEST(NurbsTessellation, CylinderHasExactRadiusAndHorizontalRadialNormals) {
  TriangleMeshData mesh = tessellate(cylinder(3));
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    const Vec3f p = mesh.P[i], n = mesh.N[i];
    EXPECT_NEAR(std::hypot(p.x, p.y), 1, kOnSurface);
    EXPECT_NEAR(n.x, p.x, kUnitNormal);
    EXPECT_NEAR(n.y, p.y, kUnitNormal);
    EXPECT_NEAR(n.z, 0, kUnitNormal);
    EXPECT_NEAR(p.z, 3 * mesh.uv[i].y, kOnSurface);
  }
  EXPECT_NEAR(mesh_area(mesh), 2 * M_PI * 3, 2 * M_PI * 3 * 2e-3);
}

TEST(NurbsTessellation, OnlyTheMinMaxPartIsTessellated) {
  // u from 1 to 2 is the quarter from 90 to 180 degrees (the knots are where the arcs meet);
  // v from 0.25 to 0.5 a quarter of the height.
  NurbsSurfaceDescription s = cylinder(4);
  s.u.min = 1, s.u.max = 2;
  s.v.min = 0.25, s.v.max = 0.5;
  TriangleMeshData mesh = tessellate(s);
  float umin = 9, umax = -9, vmin = 9, vmax = -9;
  for (size_t i = 0; i < mesh.P.size(); ++i) {
    const Vec3f p = mesh.P[i];
    EXPECT_LE(p.x, kOnSurface);
    EXPECT_GE(p.y, -kOnSurface);
    EXPECT_GE(p.z, 1 - kOnSurface);
    EXPECT_LE(p.z, 2 + kOnSurface);
    umin = std::min(umin, mesh.uv[i].x), umax = std::max(umax, mesh.uv[i].x);
    vmin = std::min(vmin, mesh.uv[i].y), vmax = std::max(vmax, mesh.uv[i].y);
  }
  EXPECT_EQ(umin, 1);
  EXPECT_EQ(umax, 2);
  EXPECT_EQ(vmin, 0.25f);
  EXPECT_EQ(vmax, 0.5f);
  EXPECT_NEAR(mesh_area(mesh), M_PI / 2, M_PI / 2 * 2e-3);  // a quarter circle of radius 1, height 1
}

TEST(NurbsTessellation, TriangleNormalsFollowDPduCrossDPdv) {
  NurbsSurfaceDescription s = sphere();
  TriangleMeshData mesh = tessellate(s);
  int checked = 0;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const Vec3f face = cross(mesh.P[b] - mesh.P[a], mesh.P[c] - mesh.P[a]);
    if (length(face) < 1e-6f) continue;  // a sliver at a pole
    const double u = (mesh.uv[a].x + mesh.uv[b].x + mesh.uv[c].x) / 3.0,
                 v = (mesh.uv[a].y + mesh.uv[b].y + mesh.uv[c].y) / 3.0;
    const SurfaceSample e = evaluate_nurbs(s, u, v);
    EXPECT_GT(dot(Vec3d(face), cross(e.dPdu, e.dPdv)), 0);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(NurbsTessellation, BadInputIsAnErrorNamingTheProblem) {
  NurbsSurfaceDescription s = cylinder(1);
  s.u.knots[4] = 0.5;  // 0 0 0 1 0.5 ...
  EXPECT_NE(error_of(s).find("uknot decreases at value 4"), std::string::npos);
  s = cylinder(1);
  s.v.knots.pop_back();
  EXPECT_NE(error_of(s).find("vknot needs nv + vorder = 4 values, found 3"), std::string::npos);
  s = cylinder(1);
  s.u.order = 0;
  EXPECT_NE(error_of(s).find("uorder must be 1 to"), std::string::npos);
  s = cylinder(1);
  s.u.order = kMaxNurbsOrder + 1;
  EXPECT_NE(error_of(s).find("uorder must be 1 to"), std::string::npos);
  s = cylinder(1);
  s.v.order = 3;  // nv = 2
  EXPECT_NE(error_of(s).find("fewer than the vorder 3"), std::string::npos);
  s = cylinder(1);
  s.u.min = s.u.max = 2;
  EXPECT_NE(error_of(s).find("umin < umax"), std::string::npos);
  s = cylinder(1);
  s.v.max = 1.5;
  EXPECT_NE(error_of(s).find("vmax <= 1"), std::string::npos);
  s = cylinder(1);
  s.points.pop_back();
  EXPECT_NE(error_of(s).find("needs 18 points, found 17"), std::string::npos);
  s = cylinder(1);
  s.points[3].w = -1;
  EXPECT_NE(error_of(s).find("point 3 has weight w = -1"), std::string::npos);
  s = cylinder(1);
  s.u.knots[0] = NAN;
  EXPECT_NE(error_of(s).find("not finite"), std::string::npos);
}

TEST(NurbsTessellation, RepeatedInteriorKnotsAndLinearOrdersStayWellFormed) {
  // Order 2 in both directions with a knot of full multiplicity inside (a C0 crease) and an
  // empty interval: a bilinear grid, every triangle flat, nothing NaN.
  NurbsSurfaceDescription s;
  s.u = {4, 2, {0, 0, 1, 1, 2, 2}, 0, 2};
  s.v = {2, 2, {0, 0, 1, 1}, 0, 1};
  s.points = {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{1, 0, 1}, 1}, {{2, 0, 1}, 1},
              {{0, 1, 0}, 1}, {{1, 1, 0}, 1}, {{1, 1, 1}, 1}, {{2, 1, 1}, 1}};
  TriangleMeshData mesh = tessellate(s);
  EXPECT_GT(mesh.triangle_count(), 0u);
}

}  // namespace
}  // namespace darc
