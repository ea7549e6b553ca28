// The exact ray / ribbon intersector against analytic hits and a brute-force reference.
#include "core/geometry/curves/curve_intersector.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "core/math/curve_basis.h"
#include "support/curve_segments.h"

namespace darc {
namespace {

using test::constant_width;
using test::single_segment;
using test::straight_x;

constexpr float kTolerance = 1e-5f;

Ray ray_z(float x, float y, float z = 0) { return Ray{{x, y, z}, {0, 0, 1}}; }

bool finite(const CurveHit& h) {
  for (float f :
       {h.t, h.u, h.v, h.p.x, h.p.y, h.p.z, h.tangent.x, h.tangent.y, h.tangent.z, h.normal.x, h.normal.y, h.normal.z})
    if (!std::isfinite(f)) return false;
  return true;
}

TEST(CurveIntersect, StraightSegmentHeadOn) {
  CurveSet set = single_segment(straight_x(), constant_width(0.2f));
  CurveHit hit;
  ASSERT_TRUE(intersect_segment(set, 0, ray_z(0.3f, 0.05f), hit));
  EXPECT_NEAR(hit.t, 5.0f, kTolerance);
  EXPECT_NEAR(hit.u, 0.65f, kTolerance);
  // Offset 0.05 of a half-width 0.1, towards cross(d, tangent) = +y.
  EXPECT_NEAR(hit.v, 0.5f, 1e-4f);
  EXPECT_NEAR(hit.p.x, 0.3f, kTolerance);
  EXPECT_NEAR(hit.p.y, 0.05f, kTolerance);
  EXPECT_NEAR(hit.p.z, 5.0f, kTolerance);
  EXPECT_NEAR(hit.tangent.x, 1.0f, kTolerance);
  EXPECT_NEAR(hit.normal.z, -1.0f, kTolerance);  // facing the ray origin

  ASSERT_TRUE(intersect_segment(set, 0, ray_z(0.3f, -0.05f), hit));
  EXPECT_NEAR(hit.v, -0.5f, 1e-4f);

  // A direction that is not unit length scales t.
  Ray slow{{0.3f, 0.05f, 0}, {0, 0, 2}};
  ASSERT_TRUE(intersect_segment(set, 0, slow, hit));
  EXPECT_NEAR(hit.t, 2.5f, kTolerance);
  // From behind: the normal still faces the origin.
  Ray back{{0.3f, 0.05f, 10}, {0, 0, -1}};
  ASSERT_TRUE(intersect_segment(set, 0, back, hit));
  EXPECT_NEAR(hit.t, 5.0f, kTolerance);
  EXPECT_NEAR(hit.normal.z, 1.0f, kTolerance);
}

TEST(CurveIntersect, HalfWidthIsTheBoundary) {
  CurveSet set = single_segment(straight_x(), constant_width(0.2f));
  CurveHit hit;
  EXPECT_TRUE(intersect_segment(set, 0, ray_z(0.0f, 0.0999f), hit));
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(0.0f, 0.1001f), hit));
  EXPECT_TRUE(intersect_segment(set, 0, ray_z(-0.7f, -0.0999f), hit));
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(-0.7f, -0.1001f), hit));
  // The ends are cut flat, perpendicular to the tangent.
  EXPECT_TRUE(intersect_segment(set, 0, ray_z(0.999f, 0.0f), hit));
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(1.001f, 0.0f), hit));
}

TEST(CurveIntersect, RayIntervalIsRespected) {
  CurveSet set = single_segment(straight_x(), constant_width(0.2f));
  CurveHit hit;
  Ray ray = ray_z(0.2f, 0.0f);
  ray.tmax = 4.9f;
  EXPECT_FALSE(intersect_segment(set, 0, ray, hit));
  ray.tmax = 5.1f;
  EXPECT_TRUE(intersect_segment(set, 0, ray, hit));
  ray.tmin = 5.05f;
  EXPECT_FALSE(intersect_segment(set, 0, ray, hit));
}

TEST(CurveIntersect, WidthTapersToZero) {
  // Width 0.4 at u = 0 down to 0 at u = 1: half-width 0.2 (1 - u).
  CurveSet set = single_segment(straight_x(), {0.4f, 0.4f * 2 / 3, 0.4f / 3, 0.0f});
  CurveHit hit;
  EXPECT_TRUE(intersect_segment(set, 0, ray_z(0.5f, 0.049f), hit));  // u = 0.75: half-width 0.05
  EXPECT_NEAR(hit.v, 0.98f, 1e-3f);
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(0.5f, 0.051f), hit));
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(1.0f, 0.0f), hit));
  // Negative widths hide the rest of the strand: 0.4 to -0.4 vanishes at u = 0.5.
  set = single_segment(straight_x(), {0.4f, 0.4f / 3, -0.4f / 3, -0.4f});
  EXPECT_TRUE(intersect_segment(set, 0, ray_z(-0.5f, 0.099f), hit));  // u = 0.25: half-width 0.1
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(-0.5f, 0.101f), hit));
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(0.5f, 0.0f), hit));
  set = single_segment(straight_x(), constant_width(-1.0f));
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(0.0f, 0.0f), hit));
}

TEST(CurveIntersect, OrientedRibbonNarrowsWithTheViewingAngle) {
  CurveSet set = single_segment(straight_x(), constant_width(0.2f));
  set.flags[0] |= kSegmentOriented;
  set.normal = {Vec3f{0, 0.6f, 0.8f}, Vec3f{0, 0.6f, 0.8f}};
  CurveHit hit;
  // |n . d| = 0.8: the half-width seen by the ray is 0.08.
  EXPECT_TRUE(intersect_segment(set, 0, ray_z(0.0f, 0.079f), hit));
  EXPECT_NEAR(hit.normal.y, -0.6f, kTolerance);
  EXPECT_NEAR(hit.normal.z, -0.8f, kTolerance);
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(0.0f, 0.081f), hit));
}

// Ray parallel to a straight strand: the ray meets the strand's near end first.
TEST(CurveIntersect, EndOnHitsTheNearEnd) {
  CurveSet set = single_segment({Vec3f{0, 0, 2}, {0, 0, 3}, {0, 0, 4}, {0, 0, 5}}, constant_width(0.2f));
  CurveHit hit;
  ASSERT_TRUE(intersect_segment(set, 0, ray_z(0.05f, 0.0f), hit));
  EXPECT_NEAR(hit.t, 2.0f, kTolerance);
  EXPECT_NEAR(hit.u, 0.0f, kTolerance);
  EXPECT_TRUE(finite(hit));
  ASSERT_TRUE(intersect_segment(set, 0, Ray{{0.05f, 0, 10}, {0, 0, -1}}, hit));
  EXPECT_NEAR(hit.t, 5.0f, kTolerance);
  EXPECT_NEAR(hit.u, 1.0f, kTolerance);
  EXPECT_TRUE(finite(hit));
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(0.15f, 0.0f), hit));
  // Same along a diagonal, where the ray-space frame is not axis aligned.
  Vec3f a{1, 2, 3}, dir = normalize(Vec3f{1, 1, 1});
  set = single_segment({a + dir * 2, a + dir * 3, a + dir * 4, a + dir * 5}, constant_width(0.2f));
  ASSERT_TRUE(intersect_segment(set, 0, Ray{a, dir}, hit));
  EXPECT_NEAR(hit.t, 2.0f, 1e-4f);
  EXPECT_TRUE(finite(hit));
}

// A bent strand whose chord is parallel to the ray: the ray-space frame has no "up" from the
// chord. x(u) = 3u(1-u), z(u) = 3u; the ray at x = 0.5 meets it first at u = (1 - sqrt(1/3)) / 2.
TEST(CurveIntersect, ChordParallelToTheRay) {
  CurveSet set = single_segment({Vec3f{0, 0, 0}, {1, 0, 1}, {1, 0, 2}, {0, 0, 3}}, constant_width(0.1f));
  CurveHit hit;
  ASSERT_TRUE(intersect_segment(set, 0, ray_z(0.5f, 0.0f, -1.0f), hit));
  double u = (1 - std::sqrt(1.0 / 3.0)) / 2;
  // Leaves are flat to width / 20 = 0.005, and the curve moves ~3.5 per unit of u here.
  const double u_tolerance = 0.005 / 3.5 * 2;
  EXPECT_NEAR(hit.u, u, u_tolerance);
  EXPECT_NEAR(hit.t, 3 * u + 1, 1e-2);  // the ribbon is crossed at a slant: t within a width
  // From the other end, the other crossing (u' = 1 - u) is the nearer one.
  ASSERT_TRUE(intersect_segment(set, 0, Ray{{0.5f, 0, 4}, {0, 0, -1}}, hit));
  EXPECT_NEAR(hit.u, 1 - u, u_tolerance);
  EXPECT_FALSE(intersect_segment(set, 0, ray_z(0.81f, 0.0f, -1.0f), hit));
}

// Far from the world origin float positions keep ~0.008 absolute precision; the offsets below
// are exact multiples of 1/128 so the expected answers are exact.
TEST(CurveIntersect, CoordinatesNear1e5) {
  const float c = 1e5f;
  CurveSet set = single_segment({Vec3f{c - 1, c, c}, {c - 1.0f / 3, c, c}, {c + 1.0f / 3, c, c}, {c + 1, c, c}},
                                constant_width(0.25f));
  CurveHit hit;
  ASSERT_TRUE(intersect_segment(set, 0, Ray{{c + 0.25f, c + 15.0f / 128, c - 10}, {0, 0, 1}}, hit));
  EXPECT_NEAR(hit.t, 10.0f, 1e-4f);
  EXPECT_NEAR(hit.u, 0.625f, 1e-4f);
  EXPECT_NEAR(hit.v, 15.0f / 16, 1e-3f);
  EXPECT_FALSE(intersect_segment(set, 0, Ray{{c + 0.25f, c + 17.0f / 128, c - 10}, {0, 0, 1}}, hit));
}

TEST(CurveIntersect, ZeroLengthSegmentNeverGivesNaN) {
  Vec3f p{1, 2, 3};
  CurveSet set = single_segment({p, p, p, p}, constant_width(0.5f));
  CurveHit hit;
  ASSERT_TRUE(intersect_segment(set, 0, Ray{{1.1f, 2, 0}, {0, 0, 1}}, hit));
  EXPECT_NEAR(hit.t, 3.0f, kTolerance);
  EXPECT_TRUE(finite(hit));
  EXPECT_NEAR(length(hit.tangent), 1.0f, kTolerance);
  EXPECT_NEAR(length(hit.normal), 1.0f, kTolerance);
  EXPECT_FALSE(intersect_segment(set, 0, Ray{{1.3f, 2, 0}, {0, 0, 1}}, hit));
  // Degenerate rays are misses, not NaN.
  EXPECT_FALSE(intersect_segment(set, 0, Ray{{1, 2, 0}, {0, 0, 0}}, hit));
  float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(intersect_segment(set, 0, Ray{{1, 2, 0}, {nan, 0, 1}}, hit));
}

// Random segments (some with coincident points, negative widths, huge offsets) and rays: every
// reported hit is finite, inside the ray interval and on the segment.
TEST(CurveIntersect, RandomInputsNeverGiveNaN) {
  std::mt19937 rng(3);  // fixed seed: deterministic
  std::uniform_real_distribution<float> coord(-2.0f, 2.0f), width(-0.2f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    float offset = (i % 4 == 0) ? 1e5f : 0.0f;
    std::array<Vec3f, 4> cp;
    for (auto& p : cp) p = Vec3f{coord(rng), coord(rng), coord(rng)} + Vec3f{offset, offset, offset};
    if (i % 7 == 0) cp[1] = cp[2] = cp[3] = cp[0];
    if (i % 5 == 0) cp[2] = cp[1];
    CurveSet set = single_segment(cp, {width(rng), width(rng), width(rng), width(rng)});
    Vec3f target = bezier_evaluate(cp.data(), std::uniform_real_distribution<float>(0, 1)(rng));
    Vec3f origin = target + Vec3f{coord(rng), coord(rng), coord(rng)} * 3.0f;
    CurveHit hit;
    if (!intersect_segment(set, 0, Ray{origin, target - origin}, hit)) continue;
    ++hits;
    ASSERT_TRUE(finite(hit)) << i;
    EXPECT_GE(hit.u, 0.0f);
    EXPECT_LE(hit.u, 1.0f);
    EXPECT_GE(hit.t, 0.0f);
    EXPECT_NEAR(length(hit.normal), 1.0f, 1e-4f);
    EXPECT_NEAR(length(hit.tangent), 1.0f, 1e-4f);
  }
  EXPECT_GT(hits, 500);
}

double bezier(const double c[4], double u) {
  double s = 1 - u;
  return s * s * s * c[0] + 3 * s * s * u * c[1] + 3 * s * u * u * c[2] + u * u * u * c[3];
}

// Nakamaru's erratum curve: control points spread unevenly along the ray. Without the z term in
// the depth estimate the leaf's u (and so t) is visibly off.
TEST(CurveIntersect, ErratumCurveGivesTheRightDepth) {
  CurveSet set = single_segment({Vec3f{0, 2, 4000}, {0, 1, 2000}, {0, -1, 1000}, {0, -2, 0}}, constant_width(0.5f));
  const double y[4] = {2, 1, -1, -2}, z[4] = {4000, 2000, 1000, 0};
  for (double u : {0.1, 0.3, 0.5, 0.8}) {
    CurveHit hit;
    ASSERT_TRUE(intersect_segment(set, 0, Ray{{0, float(bezier(y, u)), -1}, {0, 0, 1}}, hit)) << u;
    EXPECT_NEAR(hit.u, u, 1e-4) << u;
    EXPECT_NEAR(hit.t, bezier(z, u) + 1, 0.5) << u;
  }
}

// Depth ranges [near, far] (shifted by the ray origin) of the runs of consecutive samples lying
// within `radius` of the ray through (x, y) along +z: one run per branch of the curve the ray passes.
std::vector<std::pair<double, double>> branch_depths(const std::vector<Vec3d>& samples, double x, double y,
                                                     double radius, double origin_z) {
  std::vector<std::pair<double, double>> runs;
  bool inside = false;
  for (const Vec3d& s : samples) {
    double dx = s.x - x, dy = s.y - y;
    bool near = dx * dx + dy * dy <= radius * radius;
    double depth = s.z - origin_z;
    if (near && !inside) runs.push_back({depth, depth});
    if (near) runs.back() = {std::min(runs.back().first, depth), std::max(runs.back().second, depth)};
    inside = near;
  }
  return runs;
}

// Embree's self-looping Bézier (hair0.xml): the curve passes over itself, so a ray can cross
// it twice and must get the nearer crossing. Reference: dense samples of the curve. A ray must
// hit where a sample is well within half a width of it and miss where none is near; its t must
// be the depth of a branch it passes, and not behind any branch it certainly passes.
TEST(CurveIntersect, SelfLoopingCurveAgreesWithBruteForce) {
  const double px[4] = {0, 8, -4, 4}, py[4] = {0, 4, 4, 0}, pz[4] = {-2, -2, -2, -3};
  const double half_width = 0.25, origin_z = -10;
  CurveSet set =
      single_segment({Vec3f{0, 0, -2}, {8, 4, -2}, {-4, 4, -2}, {4, 0, -3}}, constant_width(float(2 * half_width)));
  constexpr int kSamples = 4000;  // ~0.004 apart along the curve
  std::vector<Vec3d> samples(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) {
    double u = double(i) / kSamples;
    samples[i] = {bezier(px, u), bezier(py, u), bezier(pz, u)};
  }
  // Disagreement is allowed within this distance of the silhouette, and at the curve's ends,
  // which the ribbon cuts flat where the reference rounds them.
  const double band = 0.01;
  const double depth_tolerance = 1e-3;
  int hits = 0, overlaps = 0;
  for (double x = -1.0; x <= 5.0; x += 0.1) {
    for (double y = -0.5; y <= 3.5; y += 0.1) {
      auto loose = branch_depths(samples, x, y, half_width + band, origin_z);
      auto certain = branch_depths(samples, x, y, half_width - band, origin_z);
      bool near_end =
          std::hypot(x - px[0], y - py[0]) < half_width + band || std::hypot(x - px[3], y - py[3]) < half_width + band;
      CurveHit hit;
      bool got = intersect_segment(set, 0, Ray{{float(x), float(y), float(origin_z)}, {0, 0, 1}}, hit);
      std::string where = "x " + std::to_string(x) + " y " + std::to_string(y);
      if (loose.empty()) {
        EXPECT_FALSE(got) << where;
      }
      if (!certain.empty() && !near_end) {
        EXPECT_TRUE(got) << where;
      }
      if (!got) continue;
      ++hits;
      if (certain.size() > 1) ++overlaps;
      EXPECT_TRUE(finite(hit));
      bool on_a_branch = false;
      for (auto [near, far] : loose) on_a_branch |= hit.t >= near - depth_tolerance && hit.t <= far + depth_tolerance;
      EXPECT_TRUE(on_a_branch) << where << " t " << hit.t;
      for (auto [near, far] : certain) EXPECT_LE(hit.t, far + depth_tolerance) << where << " behind a branch";
    }
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(overlaps, 3);  // the grid does sample the self-overlap
}

}  // namespace
}  // namespace darc
