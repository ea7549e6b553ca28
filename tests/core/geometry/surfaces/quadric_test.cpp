// The RI quadrics against the spec's own formulas (RI Spec 3.2, 5.3), written out again here so
// that the tests do not share code with what they test: the parametric point P(u, v), its
// implicit equation, and the parametric normal dP/du x dP/dv by finite differences.
#include "core/geometry/surfaces/quadric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace darc {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

// One quadric with the spec's formulas for it, in object space.
struct SpecShape {
  std::string name;
  Quadric quadric;
  std::function<Vec3d(double u, double v)> point;
  std::function<double(const Vec3d&)> implicit;  // zero on the (untrimmed) surface
  double size = 1;                               // length scale for tolerances
};

Vec3d revolve(double rho, double theta, double z) { return {rho * std::cos(theta), rho * std::sin(theta), z}; }

SpecShape cone(double h, double r, double tmax) {
  return {"Cone", Quadric::cone(h, r, tmax, Matrix4::identity()),
          [=](double u, double v) { return revolve(r * (1 - v), u * tmax * kDeg, v * h); },
          [=](const Vec3d& p) { return p.x * p.x + p.y * p.y - r * r * (1 - p.z / h) * (1 - p.z / h); },
          std::max(std::abs(h), std::abs(r))};
}

SpecShape cylinder(double r, double z0, double z1, double tmax) {
  return {"Cylinder", Quadric::cylinder(r, z0, z1, tmax, Matrix4::identity()),
          [=](double u, double v) { return revolve(r, u * tmax * kDeg, z0 + v * (z1 - z0)); },
          [=](const Vec3d& p) { return p.x * p.x + p.y * p.y - r * r; }, std::max(std::abs(r), std::abs(z1 - z0))};
}

SpecShape disk(double h, double r, double tmax) {
  return {"Disk", Quadric::disk(h, r, tmax, Matrix4::identity()),
          [=](double u, double v) { return revolve(r * (1 - v), u * tmax * kDeg, h); },
          [=](const Vec3d& p) { return p.z - h; }, std::abs(r)};
}

SpecShape paraboloid(double rmax, double z0, double z1, double tmax) {
  return {"Paraboloid", Quadric::paraboloid(rmax, z0, z1, tmax, Matrix4::identity()),
          [=](double u, double v) {
            double z = z0 + v * (z1 - z0);
            return revolve(rmax * std::sqrt(z / z1), u * tmax * kDeg, z);
          },
          [=](const Vec3d& p) { return p.x * p.x + p.y * p.y - rmax * rmax * p.z / z1; },
          std::max(std::abs(rmax), std::abs(z1))};
}

SpecShape hyperboloid(Vec3d p1, Vec3d p2, double tmax) {
  auto point = [=](double u, double v) {
    Vec3d l = p1 * (1 - v) + p2 * v;
    double t = u * tmax * kDeg;
    return Vec3d{l.x * std::cos(t) - l.y * std::sin(t), l.x * std::sin(t) + l.y * std::cos(t), l.z};
  };
  auto implicit = [=](const Vec3d& p) {
    if (p1.z == p2.z) return p.z - p1.z;
    double v = (p.z - p1.z) / (p2.z - p1.z);
    Vec3d l = p1 * (1 - v) + p2 * v;
    return p.x * p.x + p.y * p.y - (l.x * l.x + l.y * l.y);
  };
  return {"Hyperboloid", Quadric::hyperboloid(p1, p2, tmax, Matrix4::identity()), point, implicit,
          std::max(length(p1), length(p2))};
}

SpecShape torus(double major, double minor, double phi0, double phi1, double tmax) {
  return {"Torus", Quadric::torus(major, minor, phi0, phi1, tmax, Matrix4::identity()),
          [=](double u, double v) {
            double phi = (phi0 + v * (phi1 - phi0)) * kDeg;
            return revolve(major + minor * std::cos(phi), u * tmax * kDeg, minor * std::sin(phi));
          },
          [=](const Vec3d& p) {
            double k = dot(p, p) + major * major - minor * minor;
            return k * k - 4 * major * major * (p.x * p.x + p.y * p.y);
          },
          std::abs(major) + std::abs(minor)};
}

// Positive and negative radii, reversed z and phi ranges, negative and partial sweeps.
std::vector<SpecShape> all_shapes() {
  return {
      cone(2, 1, 300),
      cone(-1.5, 0.8, 360),
      cone(2, -1, -200),
      cylinder(1, -1, 1, 270),
      cylinder(-0.7, 1, -0.5, 120),
      cylinder(1, 0, 2, -300),
      disk(0.5, 1, 300),
      disk(-1, -0.6, -90),
      paraboloid(1, 0.2, 2, 300),
      paraboloid(-0.8, -0.1, -1.5, 200),
      paraboloid(1, 1.5, 0.5, 360),
      hyperboloid({1, -1, -1}, {1, 1, 1}, 300),
      hyperboloid({0.5, 0, 0}, {1, 0, 1}, -250),
      hyperboloid({0.3, 0, 0.2}, {1, 0.5, 0.2}, 300),
      hyperboloid({1, 0, 0}, {-1, 0.2, 1}, 360),
      torus(1, 0.25, 0, 360, 360),
      torus(1, 0.3, -45, 200, 270),
      torus(0.5, -0.4, 300, 30, -180),
      torus(0.4, 0.6, 0, 360, 300),  // spindle: major < minor
  };
}

// The parametric normal dP/du x dP/dv by central differences of the spec's point.
Vec3d spec_normal(const SpecShape& s, double u, double v) {
  const double h = 1e-6;
  Vec3d dpdu = (s.point(u + h, v) - s.point(u - h, v)) / (2 * h);
  Vec3d dpdv = (s.point(u, v + h) - s.point(u, v - h)) / (2 * h);
  return cross(dpdu, dpdv);
}

Vec3d implicit_gradient(const SpecShape& s, const Vec3d& p) {
  const double h = 1e-6 * s.size;
  Vec3d g;
  for (int a = 0; a < 3; ++a) {
    Vec3d dp;
    dp[a] = h;
    g[a] = (s.implicit(p + dp) - s.implicit(p - dp)) / (2 * h);
  }
  return g;
}

Ray ray_from(const Vec3d& o, const Vec3d& d) { return Ray{Vec3f(o), Vec3f(d)}; }

// Rays shot at P(u, v) along the spec's normal, from either side, find P with its (u, v), the
// normal dP/du x dP/dv (not flipped toward the ray), parallel to the implicit gradient.
TEST(Quadric, HitsTheSpecPointWithItsUVAndParametricNormal) {
  for (const SpecShape& s : all_shapes()) {
    SCOPED_TRACE(s.name);
    ASSERT_FALSE(s.quadric.degenerate);
    int checked = 0;
    for (double u = 0.05; u < 1; u += 0.1) {
      for (double v = 0.05; v < 1; v += 0.1) {
        SCOPED_TRACE(testing::Message() << "u " << u << " v " << v);
        Vec3d p = s.point(u, v);
        Vec3d n_spec = spec_normal(s, u, v);
        if (length(n_spec) < 1e-3 * s.size * s.size) continue;  // near a pole of the parametrization
        Vec3d n = normalize(n_spec);
        for (double side : {1.0, -1.0}) {
          double offset = 1e-3 * s.size;
          SurfaceHit hit;
          ASSERT_TRUE(s.quadric.intersect(ray_from(p + n * (side * offset), n * -side), hit));
          EXPECT_NEAR(hit.t, offset, 1e-5 * s.size);
          EXPECT_NEAR(length(Vec3d(hit.p) - p), 0.0, 1e-5 * s.size);
          EXPECT_NEAR(hit.u, u, 1e-5);
          EXPECT_NEAR(hit.v, v, 1e-5);
          EXPECT_GT(dot(Vec3d(hit.ng), n), 1 - 1e-6);
          EXPECT_NEAR(std::abs(dot(Vec3d(hit.ng), normalize(implicit_gradient(s, p)))), 1.0, 1e-5);
          EXPECT_GT(dot(Vec3d(s.quadric.normal_at(Vec3f(p))), n), 1 - 1e-6);
          ++checked;
        }
      }
    }
    EXPECT_GT(checked, 100);
  }
}

// Random rays: every hit lies on the implicit surface, has a unit normal, (u, v) in [0, 1] and
// lies inside the bounds; and the bounds contain every sampled spec point.
TEST(Quadric, RandomHitsLieOnTheSurfaceInsideTheBounds) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-2.5, 2.5);
  for (const SpecShape& s : all_shapes()) {
    SCOPED_TRACE(s.name);
    BBox b = s.quadric.bounds();
    auto inside = [&](const Vec3d& p) {
      return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
    };
    for (int i = 0; i <= 20; ++i) {
      for (int j = 0; j <= 20; ++j) ASSERT_TRUE(inside(s.point(i / 20.0, j / 20.0)));
    }
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
      Vec3d o{coord(rng), coord(rng), coord(rng)};
      Vec3d d = normalize(Vec3d{coord(rng), coord(rng), coord(rng)});
      SurfaceHit hit;
      if (!s.quadric.intersect(ray_from(o, d), hit)) continue;
      ++hits;
      Vec3d p(hit.p);
      double g = length(implicit_gradient(s, p));
      ASSERT_NEAR(s.implicit(p) / std::max(g, 1e-9), 0.0, 1e-5 * s.size);
      ASSERT_NEAR(length(hit.ng), 1.0f, 1e-5f);
      ASSERT_TRUE(hit.u >= 0 && hit.u <= 1 && hit.v >= 0 && hit.v <= 1);
      ASSERT_TRUE(inside(p));
    }
    EXPECT_GT(hits, 5);
  }
}

// Fraction of a grid of parallel rays that hit, times the area the grid covers.
double projected_area(const Quadric& q, const Vec3d& view, double half_extent, int n = 400) {
  Vec3d s, t;
  orthonormal_basis(normalize(view), s, t);
  int hits = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      double a = -half_extent + (i + 0.5) * (2 * half_extent / n);
      double b = -half_extent + (j + 0.5) * (2 * half_extent / n);
      SurfaceHit hit;
      hits += q.intersect(ray_from(s * a + t * b - view * 10.0, view), hit);
    }
  }
  return 4 * half_extent * half_extent * hits / double(n * n);
}

// Analytic projected areas; a 400 x 400 grid over a 3 x 3 to 6 x 6 window resolves them to
// within 1% (the error is about the outline length times the cell size).
TEST(Quadric, ProjectedAreasMatchAnalytic) {
  const Matrix4 id = Matrix4::identity();
  const double tolerance = 0.01;
  struct Case {
    const char* name;
    Quadric q;
    Vec3d view;
    double half_extent, area;
  } cases[] = {
      {"disk 270", Quadric::disk(0.5, 1, 270, id), {0, 0, 1}, 1.5, 0.75 * kPi},
      {"cylinder side", Quadric::cylinder(1, -1, 1, 360, id), {0, 1, 0}, 1.5, 4},
      {"half cylinder end-on", Quadric::cylinder(1, -1, 1, 180, id), {1, 0, 0}, 1.5, 2},
      {"cone side", Quadric::cone(2, 1, 360, id), {1, 0, 0}, 2, 2},
      {"cone top", Quadric::cone(2, 1, 360, id), {0, 0, -1}, 1.5, kPi},
      {"paraboloid side", Quadric::paraboloid(1, 0, 2, 360, id), {1, 0, 0}, 2, 8.0 / 3},
      {"hyperboloid side",
       Quadric::hyperboloid({1, -1, -1}, {1, 1, 1}, 360, id),
       {1, 0, 0},
       2,
       2 * (std::sqrt(2.0) + std::asinh(1.0))},
      {"hyperboloid along axis", Quadric::hyperboloid({1, -1, -1}, {1, 1, 1}, 360, id), {0, 0, 1}, 1.5, kPi},
      {"torus top", Quadric::torus(1, 0.25, 0, 360, 360, id), {0, 0, 1}, 1.5, 4 * kPi * 0.25},
      {"torus side", Quadric::torus(1, 0.25, 0, 360, 360, id), {1, 0, 0}, 1.5, 4 * 0.25 + kPi * 0.0625},
      {"spindle torus top", Quadric::torus(0.4, 0.6, 0, 360, 360, id), {0, 0, 1}, 1.5, kPi},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_NEAR(projected_area(c.q, c.view, c.half_extent), c.area, tolerance * c.area);
  }
}

// Rays a hair inside the exact outline hit, a hair outside miss, all round the outline.
TEST(Quadric, SilhouettesAreExact) {
  const Matrix4 id = Matrix4::identity();
  const double eps = 1e-5;
  auto hits = [](const Quadric& q, Vec3d o, Vec3d d) {
    SurfaceHit h;
    return q.intersect(ray_from(o, d), h);
  };
  Quadric cyl = Quadric::cylinder(1, -1, 1, 360, id);
  EXPECT_TRUE(hits(cyl, {1 - eps, -10, 0}, {0, 1, 0}));
  EXPECT_FALSE(hits(cyl, {1 + eps, -10, 0}, {0, 1, 0}));
  EXPECT_TRUE(hits(cyl, {0, -10, 1 - eps}, {0, 1, 0}));
  EXPECT_FALSE(hits(cyl, {0, -10, 1 + eps}, {0, 1, 0}));
  Quadric cone = Quadric::cone(2, 1, 360, id);  // side outline |y| = 1 - z / 2
  EXPECT_TRUE(hits(cone, {-10, 0.5 - eps, 1}, {1, 0, 0}));
  EXPECT_FALSE(hits(cone, {-10, 0.5 + eps, 1}, {1, 0, 0}));
  Quadric parab = Quadric::paraboloid(1, 0, 2, 360, id);  // side outline |y| = sqrt(z / 2)
  EXPECT_TRUE(hits(parab, {-10, std::sqrt(0.5) - eps, 1}, {1, 0, 0}));
  EXPECT_FALSE(hits(parab, {-10, std::sqrt(0.5) + eps, 1}, {1, 0, 0}));
  Quadric hyper = Quadric::hyperboloid({1, -1, -1}, {1, 1, 1}, 360, id);  // rho^2 = 1 + z^2
  EXPECT_TRUE(hits(hyper, {-10, std::sqrt(1.25) - eps, 0.5}, {1, 0, 0}));
  EXPECT_FALSE(hits(hyper, {-10, std::sqrt(1.25) + eps, 0.5}, {1, 0, 0}));
  EXPECT_TRUE(hits(hyper, {1 + eps, 0, -10}, {0, 0, 1}));  // the waist
  EXPECT_FALSE(hits(hyper, {1 - eps, 0, -10}, {0, 0, 1}));
  const int n = 720;
  Quadric ring = Quadric::torus(1, 0.25, 0, 360, 360, id);
  Quadric disk = Quadric::disk(0, 1, 360, id);
  int wrong = 0;
  for (int i = 0; i < n; ++i) {
    double a = 2 * kPi * (i + 0.5) / n, c = std::cos(a), s = std::sin(a);
    // Torus from above: outer rim at 1.25, hole at 0.75. From the side at height z: the outline
    // is |y| = 1 + sqrt(r^2 - z^2), and the top at z = 0.25 over the whole tube.
    wrong += !hits(ring, {(1.25 - eps) * c, (1.25 - eps) * s, 10}, {0, 0, -1});
    wrong += hits(ring, {(1.25 + eps) * c, (1.25 + eps) * s, 10}, {0, 0, -1});
    wrong += !hits(ring, {(0.75 + eps) * c, (0.75 + eps) * s, 10}, {0, 0, -1});
    wrong += hits(ring, {(0.75 - eps) * c, (0.75 - eps) * s, 10}, {0, 0, -1});
    double z = 0.25 * s, y = 1 + 0.25 * std::abs(c);
    Vec3d out = normalize(Vec3d{0, std::abs(c), s});  // outward in the y-z outline
    Vec3d o{-10, y, z};
    wrong += !hits(ring, o - out * eps, {1, 0, 0});
    wrong += hits(ring, o + out * eps, {1, 0, 0});
    wrong += !hits(disk, {(1 - eps) * c, (1 - eps) * s, -10}, {0, 0, 1});
    wrong += hits(disk, {(1 + eps) * c, (1 + eps) * s, -10}, {0, 0, 1});
  }
  EXPECT_EQ(wrong, 0);
}

// The torus outline again, from a camera 1000 sizes away and through a rotated, scaled frame.
TEST(Quadric, TorusSilhouetteFromFarAwayAndTransformed) {
  Matrix4 m = Matrix4::rotate(30, {1, 0.5, 0}) * Matrix4::scale({2, 2, 2}) * Matrix4::translate({3, -1, 2});
  Quadric ring = Quadric::torus(1, 0.25, 0, 360, 360, m);
  Vec3d axis = normalize(m.transform_vector({0, 0, 1}));
  Vec3d centre = m.transform_point({0, 0, 0});
  Vec3d s, t;
  orthonormal_basis(axis, s, t);
  const double eps = 1e-4;  // world units: the torus is 2.5 wide here; float origins at 2000
  int wrong = 0;
  for (int i = 0; i < 360; ++i) {
    double a = 2 * kPi * (i + 0.5) / 360;
    Vec3d radial = s * std::cos(a) + t * std::sin(a);
    SurfaceHit h;
    Vec3d far = centre + axis * 2000.0;
    wrong += !ring.intersect(ray_from(far + radial * (2.5 - eps), -axis), h);
    wrong += ring.intersect(ray_from(far + radial * (2.5 + eps), -axis), h);
  }
  EXPECT_EQ(wrong, 0);
}

// Rays grazing the torus at random silhouette points, offset a little off the tangent plane:
// wherever a dense sampling of the implicit function along the ray finds a sign change (the ray
// truly crosses the surface), the quartic finds a hit there.
TEST(Quadric, TorusGrazingRaysFindEveryCrossing) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  SpecShape s = torus(1, 0.25, 0, 360, 360);
  const double window = 0.02;  // the ray runs from P - w window / 2 to P + w window / 2
  const int samples = 20000;   // step 1e-6 along it
  int crossings = 0, misses = 0;
  for (int i = 0; i < 2000; ++i) {
    double u = unit(rng), v = unit(rng);
    Vec3d p = s.point(u, v);
    Vec3d n = normalize(spec_normal(s, u, v));
    Vec3d a, b;
    orthonormal_basis(n, a, b);
    double angle = 2 * kPi * unit(rng);
    Vec3d w = a * std::cos(angle) + b * std::sin(angle);  // tangent: w . n = 0
    Vec3d o = p + n * ((unit(rng) - 0.5) * 2e-4) - w * (0.5 * window);
    Ray ray{Vec3f(o), Vec3f(w)};  // the reference samples the ray as stored, in float
    ray.tmax = float(window);
    Vec3d od(ray.o), wd(ray.d);
    double first = -1, previous = s.implicit(od);
    for (int k = 1; k <= samples && first < 0; ++k) {
      double t = window * k / samples;
      double f = s.implicit(od + wd * t);
      if ((f < 0) != (previous < 0)) first = t;
      previous = f;
    }
    if (first < 0) continue;
    ++crossings;
    SurfaceHit hit;
    if (!s.quadric.intersect(ray, hit) || std::abs(hit.t - first) > 2.0 * window / samples) ++misses;
  }
  EXPECT_GT(crossings, 500);
  EXPECT_EQ(misses, 0);
}

TEST(Quadric, CutAwaySweepLetsTheRayThroughToTheFarInsideWall) {
  const Matrix4 id = Matrix4::identity();
  SurfaceHit h;
  // Cylinder kept only for theta in [0, 90]: along +x at y = 0.5 the ray first crosses the cut
  // part (theta 150) and hits the kept one (theta 30) from inside.
  Quadric quarter = Quadric::cylinder(1, -1, 1, 90, id);
  ASSERT_TRUE(quarter.intersect(Ray{{-10, 0.5f, 0}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.t, 10 + std::sqrt(0.75), 1e-5);
  EXPECT_NEAR(h.u, 1.0 / 3, 1e-5);
  EXPECT_GT(h.ng.x, 0);  // outward, away from the ray
  EXPECT_FALSE(quarter.intersect(Ray{{-10, -0.5f, 0}, {1, 0, 0}}, h));
  // Torus theta in [0, 180] (y >= 0): along +y through the centre, the tube at y = -1.25 and
  // -0.75 is cut away; the hit is the inside of the tube's near wall at y = 0.75.
  Quadric half = Quadric::torus(1, 0.25, 0, 360, 180, id);
  ASSERT_TRUE(half.intersect(Ray{{0, -10, 0}, {0, 1, 0}}, h));
  EXPECT_NEAR(h.t, 10.75, 1e-5);
  EXPECT_LT(h.ng.y, 0);  // the tube's outward normal at its inner equator points to the axis
  // Torus phi in [0, 180]: the upper half of the tube. From below the bottom is cut away and the
  // ray meets the top from inside.
  Quadric upper = Quadric::torus(1, 0.25, 0, 180, 360, id);
  ASSERT_TRUE(upper.intersect(Ray{{1, 0, -10}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.t, 10.25, 1e-5);
  EXPECT_NEAR(h.v, 0.5, 1e-5);
  EXPECT_GT(h.ng.z, 0);
  // Paraboloid clipped to z in [1, 2]: its bottom opening has radius sqrt(1/2).
  Quadric bowl = Quadric::paraboloid(1, 1, 2, 360, id);
  EXPECT_FALSE(bowl.intersect(Ray{{0.6f, 0, 10}, {0, 0, -1}}, h));
  ASSERT_TRUE(bowl.intersect(Ray{{0.8f, 0, 10}, {0, 0, -1}}, h));
  EXPECT_NEAR(h.p.z, 2 * 0.64, 1e-5);
  EXPECT_LT(h.ng.z, 0);  // the outside of the bowl faces down: seen from inside here
  // Disk theta in [0, 90].
  Quadric quarter_disk = Quadric::disk(0, 1, 90, id);
  EXPECT_FALSE(quarter_disk.intersect(Ray{{-0.5f, 0.5f, -1}, {0, 0, 1}}, h));
  ASSERT_TRUE(quarter_disk.intersect(Ray{{0.5f, 0.5f, -1}, {0, 0, 1}}, h));
  EXPECT_NEAR(h.u, 0.5, 1e-5);
  EXPECT_NEAR(h.v, 1 - std::sqrt(0.5), 1e-5);
  // Cone over theta in [0, 180]: along -y at x = 0.25, z = 0.5 (radius 0.75 there) the near
  // side is cut, the far side at y = +sqrt(0.75^2 - 0.25^2) is hit.
  Quadric half_cone = Quadric::cone(2, 1, 180, id);
  ASSERT_TRUE(half_cone.intersect(Ray{{0.25f, -10, 0.5f}, {0, 1, 0}}, h));
  EXPECT_NEAR(h.p.y, std::sqrt(0.5), 1e-5);
}

TEST(Quadric, ParametricNormalSignsFollowTheSpec) {
  const Matrix4 id = Matrix4::identity();
  SurfaceHit h;
  Ray down{{0.5f, 0.01f, 10}, {0, 0, -1}};
  ASSERT_TRUE(Quadric::disk(0, 1, 360, id).intersect(down, h));
  EXPECT_GT(h.ng.z, 0);  // +z for a positive sweep
  ASSERT_TRUE(Quadric::disk(0, 1, -360, id).intersect(down, h));
  EXPECT_LT(h.ng.z, 0);
  ASSERT_TRUE(Quadric::disk(0, -1, 360, id).intersect(down, h));
  EXPECT_GT(h.ng.z, 0);  // a negative radius only turns the disk half a turn
  Ray side{{10, 0.01f, 0.5f}, {-1, 0, 0}};
  ASSERT_TRUE(Quadric::cylinder(1, 0, 1, 360, id).intersect(side, h));
  EXPECT_GT(h.ng.x, 0);  // outward
  ASSERT_TRUE(Quadric::cylinder(1, 1, 0, 360, id).intersect(side, h));
  EXPECT_LT(h.ng.x, 0);  // reversed z range
  ASSERT_TRUE(Quadric::cone(1, 1, 360, id).intersect(Ray{{10, 0.01f, 0.5f}, {-1, 0, 0}}, h));
  EXPECT_GT(h.ng.x, 0);
  EXPECT_GT(h.ng.z, 0);                     // outward and up, (height, 0, radius) normalized
  EXPECT_NEAR(h.ng.z / h.ng.x, 1.0, 1e-3);  // 1 / cos(theta), theta = 0.02
  ASSERT_TRUE(Quadric::torus(1, 0.25, 0, 360, 360, id).intersect(Ray{{10, 0.01f, 0}, {-1, 0, 0}}, h));
  EXPECT_GT(h.ng.x, 0);  // outward from the tube
  ASSERT_TRUE(Quadric::torus(1, -0.25, 0, 360, 360, id).intersect(Ray{{10, 0.01f, 0}, {-1, 0, 0}}, h));
  EXPECT_GT(h.ng.x, 0);  // a negative minor radius only moves phi half a turn round the tube
  ASSERT_TRUE(Quadric::torus(1, 0.25, 360, 0, 360, id).intersect(Ray{{10, 0.01f, 0}, {-1, 0, 0}}, h));
  EXPECT_LT(h.ng.x, 0);  // a reversed phi range flips it
}

TEST(Quadric, UVRanges) {
  const Matrix4 id = Matrix4::identity();
  SurfaceHit h;
  // Cone: v = 0 at the base rim, 1 at the apex.
  Quadric cone = Quadric::cone(2, 1, 360, id);
  ASSERT_TRUE(cone.intersect(Ray{{0.001f, 0.001f, 10}, {0, 0, -1}}, h));
  EXPECT_NEAR(h.v, 1 - std::sqrt(2.0) * 0.001, 1e-5);
  ASSERT_TRUE(cone.intersect(Ray{{10, 0, 0.01f}, {-1, 0, 0}}, h));
  EXPECT_NEAR(h.v, 0.005, 1e-5);
  // Torus: v runs from phimin to phimax, u from 0 to thetamax.
  Quadric ring = Quadric::torus(1, 0.25, -90, 90, 360, id);
  ASSERT_TRUE(ring.intersect(Ray{{0, 10, 0}, {0, -1, 0}}, h));  // theta 90, phi 0
  EXPECT_NEAR(h.u, 0.25, 1e-5);
  EXPECT_NEAR(h.v, 0.5, 1e-5);
  // Paraboloid and cylinder: v along z from zmin to zmax, reversed ranges included.
  ASSERT_TRUE(Quadric::cylinder(1, 2, -2, 360, id).intersect(Ray{{10, 0, 1}, {-1, 0, 0}}, h));
  EXPECT_NEAR(h.v, 0.25, 1e-5);
  ASSERT_TRUE(Quadric::paraboloid(1, 0, 4, 360, id).intersect(Ray{{10, 0, 1}, {-1, 0, 0}}, h));
  EXPECT_NEAR(h.v, 0.25, 1e-5);
}

TEST(Quadric, FarOriginKeepsPrecision) {
  const Matrix4 id = Matrix4::identity();
  SurfaceHit h;
  ASSERT_TRUE(Quadric::cylinder(1, -1, 1, 360, id).intersect(Ray{{0.5f, -1e6f, 0}, {0, 1, 0}}, h));
  EXPECT_NEAR(h.p.y, -std::sqrt(0.75f), 1e-3);
  ASSERT_TRUE(Quadric::torus(1, 0.25, 0, 360, 360, id).intersect(Ray{{1, 0, 1e6f}, {0, 0, -1}}, h));
  EXPECT_NEAR(h.p.z, 0.25f, 1e-3);
}

TEST(Quadric, TorusWithZeroMajorRadiusIsTheSphere) {
  Quadric ball = Quadric::torus(0, 1, -90, 90, 360, Matrix4::identity());
  SurfaceHit h;
  ASSERT_TRUE(ball.intersect(Ray{{0.6f, 0, -5}, {0, 0, 1}}, h));  // a double root of the quartic
  EXPECT_NEAR(h.t, 4.2, 1e-5);
  EXPECT_NEAR(h.ng.x, 0.6, 1e-5);
  EXPECT_NEAR(h.ng.z, -0.8, 1e-5);
}

TEST(Quadric, ConeOfHeightZeroIsTheDisk) {
  Quadric flat = Quadric::cone(0, 1, 360, Matrix4::identity());
  EXPECT_EQ(flat.kind, QuadricKind::Disk);
  SurfaceHit h;
  ASSERT_TRUE(flat.intersect(Ray{{0.5f, 0, 1}, {0, 0, -1}}, h));
  EXPECT_NEAR(h.v, 0.5, 1e-6);
}

TEST(Quadric, DegenerateInputNeverHitsNorProducesNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Matrix4 id = Matrix4::identity();
  const Quadric degenerate[] = {
      Quadric::cone(1, 0, 360, id),
      Quadric::cone(1, 1, 0, id),
      Quadric::cone(nan, 1, 360, id),
      Quadric::cylinder(0, -1, 1, 360, id),
      Quadric::cylinder(1, 0.5, 0.5, 360, id),
      Quadric::cylinder(1, -1, 1, 360, Matrix4::scale({0, 1, 1})),
      Quadric::disk(0, 0, 360, id),
      Quadric::disk(0, 1, nan, id),
      Quadric::paraboloid(1, 0, 0, 360, id),
      Quadric::paraboloid(0, 0, 1, 360, id),
      Quadric::hyperboloid({1, 0, 0}, {1, 0, 0}, 360, id),
      Quadric::hyperboloid({0, 0, 0}, {0, 0, 1}, 360, id),
      Quadric::hyperboloid({nan, 0, 0}, {1, 0, 1}, 360, id),
      Quadric::torus(1, 0, 0, 360, 360, id),
      Quadric::torus(1, 0.25, 30, 30, 360, id),
      Quadric::torus(1, 0.25, 0, 360, 0, id),
  };
  for (const Quadric& q : degenerate) {
    EXPECT_TRUE(q.degenerate);
    EXPECT_TRUE(q.bounds().empty());
    SurfaceHit h;
    for (int a = 0; a < 3; ++a) {
      Vec3f d;
      d[a] = 1;
      EXPECT_FALSE(q.intersect(Ray{d * -5.0f + Vec3f{0.1f, 0.2f, 0.3f}, d}, h));
    }
  }
  Quadric ring = Quadric::torus(1, 0.25, 0, 360, 360, id);
  SurfaceHit h;
  const float fnan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(ring.intersect(Ray{{1, 0, -5}, {0, 0, 0}}, h));
  EXPECT_FALSE(ring.intersect(Ray{{1, 0, -5}, {fnan, 0, 1}}, h));
  Vec3f n = ring.normal_at({0, 0, 0});  // on the axis: any unit vector, never NaN
  EXPECT_NEAR(length(n), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace darc
