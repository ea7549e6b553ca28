// Analytic polygon coverage (core/footprint/polygon_coverage.h) against what it replaces: the
// fraction of a dense grid of the footprint's sub-rays that hit the polygon (exact ray tests),
// and the properties a mesh needs: pieces that share edges add up to exactly what they cover
// together, with disjoint masks (no crack, no double coverage).
#include "core/footprint/polygon_coverage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace darc {
namespace {

// A camera ray along +z from the origin whose footprint is `width` wide at distance 1.
Ray camera_ray(Vec3f d = {0, 0, 1}) { return Ray{{0, 0, 0}, d, 0, std::numeric_limits<float>::infinity()}; }
RayFootprint camera_footprint(float width) {
  return pencil_footprint({}, {}, {width, 0, 0}, {0, width, 0}, 0, 0);
}

FootprintFrame frame_of(const Ray& ray, const RayFootprint& f) {
  FootprintFrame frame;
  EXPECT_TRUE(FootprintFrame::make(ray, f, frame));
  return frame;
}

// Whether the sub-ray (u, v) meets the triangle within the frame's interval (double precision).
bool sub_ray_hits(const FootprintFrame& fr, double u, double v, const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  const Vec3d o = fr.origin(u, v), d = fr.direction(u, v);
  const Vec3d e1 = Vec3d(b) - Vec3d(a), e2 = Vec3d(c) - Vec3d(a);
  const Vec3d p = cross(d, e2);
  const double det = dot(e1, p);
  if (det == 0) return false;
  const Vec3d s = o - Vec3d(a);
  const double bu = dot(s, p) / det;
  const Vec3d q = cross(s, e1);
  const double bv = dot(d, q) / det;
  const double t = dot(e2, q) / det;
  return bu >= 0 && bv >= 0 && bu + bv <= 1 && t >= fr.t_min && t <= fr.t_max;
}

// The fraction of an n x n grid of sub-rays that hit the convex polygon (fanned from corner 0).
double brute_coverage(const FootprintFrame& fr, const std::vector<Vec3f>& poly, int n = 256) {
  int hits = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = (i + 0.5) / n - 0.5, v = (j + 0.5) / n - 0.5;
      for (size_t k = 1; k + 1 < poly.size(); ++k)
        if (sub_ray_hits(fr, u, v, poly[0], poly[k], poly[k + 1])) {
          ++hits;
          break;
        }
    }
  return double(hits) / (double(n) * n);
}

float coverage_of(const FootprintFrame& fr, const std::vector<Vec3f>& poly, PolygonFootprintHit* out = nullptr) {
  PolygonFootprintHit h;
  const bool hit = polygon_coverage(fr, poly, h);
  if (out) *out = h;
  return hit ? h.coverage : 0.0f;
}

TEST(PolygonCoverage, AHalfPlaneThroughTheCentreCoversHalf) {
  // A huge triangle whose edge runs through the footprint's centre at 45 degrees, at depth 2.
  const FootprintFrame fr = frame_of(camera_ray(), camera_footprint(0.01f));
  const std::vector<Vec3f> poly{{-100, 100, 2}, {100, -100, 2}, {100, 100, 2}};
  PolygonFootprintHit h;
  ASSERT_GT(coverage_of(fr, poly, &h), 0.0f);
  EXPECT_NEAR(h.coverage, 0.5, 1e-6);
  EXPECT_NEAR(h.t, 2.0, 1e-5);
  // 28 points strictly inside and the 8 on the diagonal go to one side only: 28 or 36.
  const int points = mask_count(h.mask);
  EXPECT_TRUE(points == 28 || points == 36) << points;
  // The centre lies on its edge, which counts as covered: it is shaded there.
  EXPECT_TRUE(h.covers_centre);
  EXPECT_EQ(h.u, 0.0f);
  EXPECT_EQ(h.v, 0.0f);
}

TEST(PolygonCoverage, AnOffsetEdgeCoversItsExactArea) {
  // Edge u + v = 0.25 (in footprint units): the uncovered corner triangle has legs 0.75.
  const float w = 0.01f;
  const FootprintFrame fr = frame_of(camera_ray(), camera_footprint(w));
  const float c = 0.25f * w * 3;  // at depth 3, footprint coordinate 0.25 along u+v
  const std::vector<Vec3f> poly{{-100 + c, 100, 3}, {100 + c, -100, 3}, {100, 100, 3}};
  // The region u + v >= 0.25 of the footprint: a corner triangle with legs 0.75.
  PolygonFootprintHit h;
  EXPECT_NEAR(coverage_of(fr, poly, &h), 0.5 * 0.75 * 0.75, 1e-5);
  // The centre is not covered: shaded at the covered corner's centroid, a third of the way in.
  EXPECT_FALSE(h.covers_centre);
  EXPECT_NEAR(h.u, 0.5 - 0.75 / 3, 1e-5);
  EXPECT_NEAR(h.v, 0.5 - 0.75 / 3, 1e-5);
  EXPECT_NEAR(coverage_of(fr, poly), brute_coverage(fr, poly), 2.0 / 256);
}

TEST(PolygonCoverage, MatchesDenseSubRaysOnRandomTriangles) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(-0.03f, 0.03f), depth(1.0f, 4.0f);
  const FootprintFrame fr = frame_of(camera_ray(), camera_footprint(0.02f));
  int tested = 0;
  for (int i = 0; i < 200; ++i) {
    const std::vector<Vec3f> poly{{pos(rng), pos(rng), depth(rng)}, {pos(rng), pos(rng), depth(rng)},
                                  {pos(rng), pos(rng), depth(rng)}};
    const double brute = brute_coverage(fr, poly, 128);
    EXPECT_NEAR(coverage_of(fr, poly), brute, 0.02) << "triangle " << i;
    tested += brute > 0;
  }
  EXPECT_GT(tested, 50);
}

TEST(PolygonCoverage, TwoTrianglesSharingADiagonalAddUpWithDisjointMasks) {
  const FootprintFrame fr = frame_of(camera_ray(), camera_footprint(0.01f));
  // A square from (-0.3, -0.2) to (0.4, 0.35) in footprint units at depth 1, split on a diagonal.
  const float w = 0.01f;
  const Vec3f a{-0.3f * w, -0.2f * w, 1}, b{0.4f * w, -0.2f * w, 1}, c{0.4f * w, 0.35f * w, 1}, d{-0.3f * w, 0.35f * w, 1};
  PolygonFootprintHit h1, h2, hq;
  ASSERT_TRUE(polygon_coverage(fr, std::vector<Vec3f>{a, b, c}, h1));
  ASSERT_TRUE(polygon_coverage(fr, std::vector<Vec3f>{a, c, d}, h2));
  ASSERT_TRUE(polygon_coverage(fr, std::vector<Vec3f>{a, b, c, d}, hq));
  EXPECT_NEAR(h1.coverage + h2.coverage, 0.7 * 0.55, 1e-5);
  EXPECT_NEAR(hq.coverage, 0.7 * 0.55, 1e-5);
  EXPECT_EQ(h1.mask & h2.mask, 0u) << "a mask point on the diagonal belongs to one piece only";
  EXPECT_EQ(h1.mask | h2.mask, hq.mask);
}

TEST(PolygonCoverage, AFanAroundAVertexCoversTheFootprintOnce) {
  // Eight triangles around a vertex inside the footprint, out to far beyond it, at varying depth
  // (a cone's tip): their coverages add up to 1 and their masks partition the footprint.
  const FootprintFrame fr = frame_of(camera_ray(), camera_footprint(0.01f));
  const Vec3f centre{0.0012f, -0.0007f, 2.0f};
  std::vector<Vec3f> ring;
  for (int k = 0; k < 8; ++k) {
    const double angle = 2 * M_PI * k / 8 + 0.1;
    ring.push_back({float(std::cos(angle)), float(std::sin(angle)), 2.5f});
  }
  double sum = 0;
  CoverageMask all = 0;
  for (int k = 0; k < 8; ++k) {
    PolygonFootprintHit h;
    if (!polygon_coverage(fr, std::vector<Vec3f>{centre, ring[size_t(k)], ring[size_t((k + 1) % 8)]}, h)) continue;
    sum += h.coverage;
    EXPECT_EQ(all & h.mask, 0u) << "piece " << k;
    all |= h.mask;
  }
  EXPECT_NEAR(sum, 1.0, 1e-5);
  EXPECT_EQ(all, kFullMask);
}

TEST(PolygonCoverage, APerturbedMeshCoveringTheFootprintHasNoCrack) {
  // The crack test (footprint-everything.md): a grid mesh with jittered vertices covering every
  // footprint, seen through 300 random footprints: coverage 1 and a full mask, each mask point
  // owned by exactly one triangle.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f), z(-0.2f, 0.2f);
  const int n = 12;
  const float cell = 0.002f;
  std::vector<Vec3f> grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool edge = i == 0 || j == 0 || i == n || j == n;
      const float x = (float(i) - n / 2.0f + (edge ? 0 : jitter(rng))) * cell;
      const float y = (float(j) - n / 2.0f + (edge ? 0 : jitter(rng))) * cell;
      grid.push_back({x * 10, y * 10, 10 + z(rng)});
    }
  std::uniform_real_distribution<float> dir(-0.004f, 0.004f), width(0.0005f, 0.004f);
  for (int trial = 0; trial < 300; ++trial) {
    const Ray ray = camera_ray(normalize(Vec3f{dir(rng), dir(rng), 1}));
    const float w = width(rng);
    const FootprintFrame fr = frame_of(ray, pencil_footprint({}, {}, {w, 0, 0}, {0, w * 0.7f, 0.0002f}, 0, 0));
    double sum = 0;
    std::vector<int> owners(64, 0);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3f& v00 = grid[size_t(j * (n + 1) + i)];
        const Vec3f& v10 = grid[size_t(j * (n + 1) + i + 1)];
        const Vec3f& v01 = grid[size_t((j + 1) * (n + 1) + i)];
        const Vec3f& v11 = grid[size_t((j + 1) * (n + 1) + i + 1)];
        for (const std::vector<Vec3f>& tri : {std::vector<Vec3f>{v00, v10, v11}, std::vector<Vec3f>{v00, v11, v01}}) {
          PolygonFootprintHit h;
          if (!polygon_coverage(fr, tri, h)) continue;
          sum += h.coverage;
          for (int b = 0; b < 64; ++b) owners[size_t(b)] += int((h.mask >> b) & 1);
        }
      }
    ASSERT_NEAR(sum, 1.0, 1e-4) << "trial " << trial;
    for (int b = 0; b < 64; ++b) ASSERT_EQ(owners[size_t(b)], 1) << "trial " << trial << " point " << b;
  }
}

TEST(PolygonCoverage, ACornerBehindTheCameraIsClippedLikeSubRays) {
  // A triangle reaching behind the camera (one corner at z < 0): the pencil's apex planes need no
  // clipping; the coverage equals the dense sub-rays'.
  const FootprintFrame fr = frame_of(camera_ray(), camera_footprint(0.02f));
  const std::vector<Vec3f> poly{{-0.01f, -0.01f, 1}, {0.02f, -0.005f, 1.5f}, {0.002f, 0.5f, -3}};
  const double brute = brute_coverage(fr, poly);
  EXPECT_GT(brute, 0.05);
  EXPECT_NEAR(coverage_of(fr, poly), brute, 2.0 / 256);
}

TEST(PolygonCoverage, AShadowPencilSeesTheOccluderBetweenReceiverAndLight) {
  // A shadow ray from a receiving patch 0.2 wide at the origin toward a light 10 above: the pencil
  // meets at the light. An occluder square at height 5 covering x > 0 half-covers the pencil.
  const float distance = 10;
  const Vec3f dpdx{0.2f, 0, 0}, dpdy{0, 0.2f, 0};
  const RayFootprint f = pencil_footprint(dpdx, dpdy, dpdx * (-1 / distance), dpdy * (-1 / distance), distance, 0);
  const Ray ray{{0, 0, 0}, {0, 0, 1}, 1e-4f, distance};
  const FootprintFrame fr = frame_of(ray, f);
  EXPECT_EQ(fr.side, -1);
  const std::vector<Vec3f> occluder{{0, -1, 5}, {1, -1, 5}, {1, 1, 5}, {0, 1, 5}};
  EXPECT_NEAR(coverage_of(fr, occluder), 0.5, 1e-5);
  EXPECT_NEAR(coverage_of(fr, occluder), brute_coverage(fr, occluder), 2.0 / 256);
  // Beyond the light (z = 12) or behind the receiver (z = -1) it covers nothing.
  EXPECT_EQ(coverage_of(fr, {{-1, -1, 12}, {1, -1, 12}, {1, 1, 12}, {-1, 1, 12}}), 0.0f);
  EXPECT_EQ(coverage_of(fr, {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}}), 0.0f);
}

TEST(PolygonCoverage, AParallelPrismCoversWhatItsOriginsSee) {
  // Orthographic (parallel) footprint 0.1 wide, looking along +z: a triangle covering x > 0.025.
  const RayFootprint f{{0.1f, 0, 0}, {0, 0.1f, 0}, {}, {}, 0, FootprintForm::Parallel, 0};
  const FootprintFrame fr = frame_of(camera_ray(), f);
  const std::vector<Vec3f> poly{{0.025f, -10, 2}, {10, 0, 3}, {0.025f, 10, 2}};
  EXPECT_NEAR(coverage_of(fr, poly), 0.25, 1e-5);
  EXPECT_NEAR(coverage_of(fr, poly), brute_coverage(fr, poly), 2.0 / 256);
}

TEST(PolygonCoverage, EdgeOnAndOutsideCoverNothing) {
  const FootprintFrame fr = frame_of(camera_ray(), camera_footprint(0.01f));
  PolygonFootprintHit h;
  // Seen edge-on from the apex (its plane holds the origin).
  EXPECT_FALSE(polygon_coverage(fr, std::vector<Vec3f>{{0, -1, 1}, {0, 1, 1}, {0, 0, 3}}, h));
  // Beside the footprint.
  EXPECT_FALSE(polygon_coverage(fr, std::vector<Vec3f>{{1, 1, 1}, {2, 1, 1}, {1, 2, 1}}, h));
  // Degenerate (repeated corners).
  EXPECT_FALSE(polygon_coverage(fr, std::vector<Vec3f>{{0, 0, 1}, {0, 0, 1}, {1, 0, 1}}, h));
}

// The frame's side planes (the early rejection of pieces beside the footprint): every sub-ray
// point of the square lies inside all four, for a camera pencil, a shadow pencil (before its
// apex) and a parallel prism; a point just past an edge of the square lies outside that edge's
// plane; a small triangle wholly past an edge is rejected, one straddling it is not.
TEST(PolygonCoverage, SidePlanesHoldTheFootprintAndRejectWhatLiesBeside) {
  const float distance = 10;
  const Vec3f dpdx{0.2f, 0, 0}, dpdy{0, 0.2f, 0};
  const Ray camera = camera_ray(normalize(Vec3f{0.1f, -0.2f, 1})), shadow{{0, 0, 0}, {0, 0, 1}, 1e-4f, distance};
  const RayFootprint parallel{{0.1f, 0, 0}, {0, 0.1f, 0}, {}, {}, 0, FootprintForm::Parallel, 0};
  const FootprintFrame frames[3] = {
      frame_of(camera, camera_footprint(0.02f)),
      frame_of(shadow, pencil_footprint(dpdx, dpdy, dpdx * (-1 / distance), dpdy * (-1 / distance), distance, 0)),
      frame_of(camera_ray(), parallel)};
  const double ts[3][3] = {{0.5, 2, 9}, {0.5, 5, 9.5}, {0.5, 2, 9}};
  for (int f = 0; f < 3; ++f) {
    const FootprintFrame& fr = frames[f];
    auto at = [&](double u, double v, double t) { return fr.origin(u, v) + fr.direction(u, v) * t; };
    for (double t : ts[f]) {
      for (double u : {-0.49, 0.0, 0.49})
        for (double v : {-0.49, 0.0, 0.49})
          EXPECT_FALSE(fr.outside_a_side(std::vector<Vec3f>{Vec3f(at(u, v, t))})) << f << " " << u << " " << v;
      for (int k = 0; k < 4; ++k) {
        const double u = k == 0 ? -0.55 : k == 1 ? 0.55 : 0.0, v = k == 2 ? -0.55 : k == 3 ? 0.55 : 0.0;
        EXPECT_TRUE(fr.outside_a_side(std::vector<Vec3f>{Vec3f(at(u, v, t))})) << f << " side " << k << " t " << t;
        // A triangle past that edge, and one reaching back over it.
        const double du = u * 0.2, dv = v * 0.2;
        const std::vector<Vec3f> past{Vec3f(at(u, v, t)), Vec3f(at(u + du, v + dv, t)), Vec3f(at(u + dv, v + du, t))};
        EXPECT_TRUE(fr.outside_a_side(past)) << f << " side " << k;
        const std::vector<Vec3f> over{Vec3f(at(u, v, t)), Vec3f(at(0, 0, t)), Vec3f(at(u + dv, v + du, t))};
        EXPECT_FALSE(fr.outside_a_side(over)) << f << " side " << k;
      }
    }
  }
}

}  // namespace
}  // namespace darc
