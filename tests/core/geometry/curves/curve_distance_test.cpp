// The distance-aware curve intersector against analytic coverage: a straight strand under a
// known footprint (orthographic and perspective), clipping, culling, strand ends versus
// joints, and degenerate input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "core/geometry/curves/curve_distance_intersector.h"
#include "core/geometry/curves/curve_intersector.h"
#include "support/curve_segments.h"

namespace darc {
namespace {

using test::constant_width;
using test::single_segment;
using test::straight_x;

constexpr float kTolerance = 1e-5f;

// An orthographic footprint: a square of side `side` whatever the depth.
RayFootprint orthographic(float side) {
  RayFootprint f;
  f.dox = Vec3f{side, 0, 0};
  f.doy = Vec3f{0, side, 0};
  return f;
}

struct Probe {
  bool hit;
  CurveFragmentHit h;
};
Probe probe(const CurveSet& set, const Ray& ray, const RayFootprint& fp, CoverageModel model = CoverageModel::Square,
            SegmentEnds ends = {}) {
  Probe p;
  p.hit = intersect_segment_distance(set, 0, ray, fp, model, ends, p.h);
  return p;
}

TEST(CurveDistance, StraightStrandSquareCoverageIsAnalytic) {
  CurveSet set = single_segment(straight_x(), constant_width(0.4f));
  // Centred: the band [-0.2, 0.2] inside the unit footprint.
  Probe centred = probe(set, Ray{{0.3f, 0, 0}, {0, 0, 1}}, orthographic(1));
  ASSERT_TRUE(centred.hit);
  EXPECT_NEAR(centred.h.coverage, 0.4f, kTolerance);
  EXPECT_NEAR(centred.h.t, 5.0f, kTolerance);
  EXPECT_NEAR(centred.h.u, 0.65f, kTolerance);
  EXPECT_NEAR(centred.h.distance, 0.0f, kTolerance);
  // Offset 0.4: the band [0.2, 0.6] is 0.3 inside; offset 0.6: [0.4, 0.8], 0.1 inside.
  Probe offset = probe(set, Ray{{0, 0.4f, 0}, {0, 0, 1}}, orthographic(1));
  ASSERT_TRUE(offset.hit);
  EXPECT_NEAR(offset.h.coverage, 0.3f, kTolerance);
  EXPECT_NEAR(offset.h.distance, 0.4f, kTolerance);
  Probe edge = probe(set, Ray{{0, -0.6f, 0}, {0, 0, 1}}, orthographic(1));
  ASSERT_TRUE(edge.hit);
  EXPECT_NEAR(edge.h.coverage, 0.1f, kTolerance);
  // Beyond the footprint: nothing.
  EXPECT_FALSE(probe(set, Ray{{0, 0.71f, 0}, {0, 0, 1}}, orthographic(1)).hit);
  // Wider than the footprint: saturates at 1.
  Probe wide = probe(set, Ray{{0, 0.1f, 0}, {0, 0, 1}}, orthographic(0.2f));
  ASSERT_TRUE(wide.hit);
  EXPECT_NEAR(wide.h.coverage, 1.0f, kTolerance);
}

TEST(CurveDistance, BoxAndDiscModelsAreTheirFormulas) {
  CurveSet set = single_segment(straight_x(), constant_width(0.4f));
  Ray ray{{0, 0.1f, 0}, {0, 0, 1}};
  Probe box = probe(set, ray, orthographic(1), CoverageModel::Box);
  ASSERT_TRUE(box.hit);
  EXPECT_NEAR(box.h.coverage, coverage_box(0.1f, 0.2f, 0.5f), kTolerance);  // r = half the spacing
  Probe disc = probe(set, ray, orthographic(1), CoverageModel::Disc);
  ASSERT_TRUE(disc.hit);
  EXPECT_NEAR(disc.h.coverage, coverage_disc(0.1f, 0.2f, std::sqrt(1.0f / std::numbers::pi_v<float>)), kTolerance);
}

TEST(CurveDistance, PerspectiveFootprintGrowsWithDepth) {
  CurveSet set = single_segment(straight_x(), constant_width(0.01f));
  RayFootprint fp;
  fp.ddx = Vec3f{0.01f, 0, 0};  // 0.05 wide at depth 5
  fp.ddy = Vec3f{0, 0.01f, 0};
  Probe p = probe(set, Ray{{0, 0, 0}, {0, 0, 1}}, fp);
  ASSERT_TRUE(p.hit);
  EXPECT_NEAR(p.h.coverage, 0.2f, 1e-4f);
  EXPECT_NEAR(p.h.t, 5.0f, kTolerance);
  // A non-unit direction: t is in units of the direction, the footprint per unit of t.
  RayFootprint fp2 = fp;
  fp2.ddx = fp.ddx * 2.0f;
  fp2.ddy = fp.ddy * 2.0f;
  Probe fast = probe(set, Ray{{0, 0, 0}, {0, 0, 2}}, fp2);
  ASSERT_TRUE(fast.hit);
  EXPECT_NEAR(fast.h.t, 2.5f, kTolerance);
  EXPECT_NEAR(fast.h.coverage, 0.2f, 1e-4f);
}

TEST(CurveDistance, RayIntervalClipsTheFragment) {
  CurveSet set = single_segment(straight_x(), constant_width(0.4f));
  Ray ray{{0, 0, 0}, {0, 0, 1}};
  ray.tmax = 4.9f;
  EXPECT_FALSE(probe(set, ray, orthographic(1)).hit);
  ray.tmax = 10.0f;
  ray.tmin = 5.1f;
  EXPECT_FALSE(probe(set, ray, orthographic(1)).hit);
  ray.tmin = 4.9f;
  EXPECT_TRUE(probe(set, ray, orthographic(1)).hit);
}

TEST(CurveDistance, StrandEndsFallOffJointsDoNot) {
  CurveSet set = single_segment(straight_x(), constant_width(0.4f));
  Ray at_end{{1, 0, 0}, {0, 0, 1}};
  // A joint: the next segment carries on, the footprint is fully beside the strand.
  Probe joint = probe(set, at_end, orthographic(1));
  ASSERT_TRUE(joint.hit);
  EXPECT_NEAR(joint.h.coverage, 0.4f, kTolerance);
  // A strand end through the footprint centre: half of the footprint is on the strand's side.
  Probe end = probe(set, at_end, orthographic(1), CoverageModel::Square, SegmentEnds{false, true});
  ASSERT_TRUE(end.hit);
  EXPECT_NEAR(end.h.coverage, 0.2f, kTolerance);
  // A quarter footprint before the start: a quarter of the footprint is on the strand's side.
  Probe start =
      probe(set, Ray{{-0.75f, 0, 0}, {0, 0, 1}}, orthographic(1), CoverageModel::Square, SegmentEnds{true, false});
  ASSERT_TRUE(start.hit);
  EXPECT_NEAR(start.h.coverage, 0.4f * 0.75f, kTolerance);
}

TEST(CurveDistance, StrandShorterThanTheFootprintCoversOnlyItsLength) {
  // A strand 0.2 long and 0.4 wide inside a unit footprint: 0.08 of it, not the 0.4 of a long
  // strand (the two end fall-offs cut a slab, they do not multiply).
  CurveSet set =
      single_segment({Vec3f{-0.1f, 0, 5}, {-0.1f / 3, 0, 5}, {0.1f / 3, 0, 5}, {0.1f, 0, 5}}, constant_width(0.4f));
  Probe p = probe(set, Ray{{0, 0, 0}, {0, 0, 1}}, orthographic(1), CoverageModel::Square, SegmentEnds{true, true});
  ASSERT_TRUE(p.hit);
  EXPECT_NEAR(p.h.coverage, 0.08f, 1e-4f);
}

TEST(CurveDistance, EndOnStrandIsADisc) {
  // Seen along its length, a ribbon facing the ray is a disc of its width: pi (0.2)^2 of a unit
  // footprint, not the 0.4 of a band.
  CurveSet set = single_segment({Vec3f{0, 0, 2}, {0, 0, 4}, {0, 0, 6}, {0, 0, 8}}, constant_width(0.4f));
  Probe p = probe(set, Ray{{0, 0, 0}, {0, 0, 1}}, orthographic(1), CoverageModel::Square, SegmentEnds{true, true});
  ASSERT_TRUE(p.hit);
  EXPECT_NEAR(p.h.coverage, std::numbers::pi_v<float> * 0.04f, 1e-4f);
  EXPECT_NEAR(p.h.t, 2.0f, kTolerance);  // the near end
}

TEST(CurveDistance, EndsDoNotCutACurveThatSwingsBackAcrossThem) {
  // A single-segment strand starting at (-3, 0) heading down-right, swinging round and ending at
  // (3, 0.5): its middle crosses the start's line far from the start, where it must be seen.
  CurveSet set =
      single_segment({Vec3f{-3, 0, 5}, {4.17f, -9.92f, 5}, {-4.17f, 10.5f, 5}, {3, 0.5f, 5}}, constant_width(0.8f));
  SegmentEnds both{true, true};
  // Points of the curve itself (u = 0.3 and 0.7), probed with a small footprint.
  for (float u : {0.3f, 0.7f}) {
    float s = 1 - u;
    Vec3f p =
        set.cp[0] * (s * s * s) + set.cp[1] * (3 * s * s * u) + set.cp[2] * (3 * s * u * u) + set.cp[3] * (u * u * u);
    Probe hit = probe(set, Ray{{p.x, p.y, 0}, {0, 0, 1}}, orthographic(0.1f), CoverageModel::Square, both);
    ASSERT_TRUE(hit.hit) << u;
    EXPECT_NEAR(hit.h.coverage, 1.0f, 1e-4f) << u;
  }
}

TEST(CurveDistance, ASegmentWiderThanLongCoversTheFanOfItsNormals) {
  // 6 long, 30 wide, zig-zagging: the tangent is at +24 degrees at both ends and -13 in the
  // middle, at (0, 0). The exact ribbon is the union of the lines normal to the strand (within
  // the half-width), which fan out past the end lines into a bow-tie whose edges are the middle
  // normal.
  CurveSet set = single_segment({Vec3f{-3, 0, 5}, {-1, 0.9f, 5}, {1, -0.9f, 5}, {3, 0, 5}}, constant_width(30));
  SegmentEnds both{true, true};
  const float mid_length = std::hypot(8.0f, 1.8f);
  // The middle tangent and normal.
  const float tx = 8.0f / mid_length, ty = -1.8f / mid_length;
  const float nx = -ty, ny = tx;
  // 12 along the middle normal and 2 inside the fan, either way: past the end line (up) or the
  // start line (down), where the end lines alone cut everything away.
  for (float side : {1.0f, -1.0f}) {
    Ray ray{{side * (12 * nx - 2 * tx), side * (12 * ny - 2 * ty), 0}, {0, 0, 1}};
    Probe p = probe(set, ray, orthographic(0.5f), CoverageModel::Square, both);
    ASSERT_TRUE(p.hit) << side;
    EXPECT_NEAR(p.h.coverage, 1.0f, kTolerance) << side;
  }
  // Past the end line and 3 outside the fan's edge: not covered.
  Probe outside = probe(set, Ray{{12 * nx + 3 * tx, 12 * ny + 3 * ty, 0}, {0, 0, 1}}, orthographic(0.5f),
                        CoverageModel::Square, both);
  EXPECT_TRUE(!outside.hit || outside.h.coverage <= kTolerance);
}

TEST(CurveDistance, HiddenWidthsAndBadRaysReturnNothing) {
  CurveSet zero = single_segment(straight_x(), constant_width(0.0f));
  CurveSet negative = single_segment(straight_x(), constant_width(-0.3f));
  Ray ray{{0, 0, 0}, {0, 0, 1}};
  EXPECT_FALSE(probe(zero, ray, orthographic(1)).hit);
  EXPECT_FALSE(probe(negative, ray, orthographic(1)).hit);
  CurveSet set = single_segment(straight_x(), constant_width(0.4f));
  EXPECT_FALSE(probe(set, Ray{{std::nanf(""), 0, 0}, {0, 0, 1}}, orthographic(1)).hit);
  EXPECT_FALSE(probe(set, Ray{{0, 0, 0}, {0, std::nanf(""), 1}}, orthographic(1)).hit);
  EXPECT_FALSE(probe(set, Ray{{0, 0, 0}, {0, 0, 0}}, orthographic(1)).hit);
  // Width negative at one end, positive at the other: the visible half only.
  CurveSet half = single_segment(straight_x(), {-0.4f, -0.4f / 3, 0.4f / 3, 0.4f});
  EXPECT_FALSE(probe(half, Ray{{-0.5f, 0, 0}, {0, 0, 1}}, orthographic(0.01f)).hit);
  EXPECT_TRUE(probe(half, Ray{{0.5f, 0, 0}, {0, 0, 1}}, orthographic(0.01f)).hit);
}

TEST(CurveDistance, NoFootprintIsAHitTest) {
  CurveSet set = single_segment(straight_x(), constant_width(0.4f));
  RayFootprint none;
  none.min_radius = 1e-7f;
  Probe inside = probe(set, Ray{{0, 0.19f, 0}, {0, 0, 1}}, none);
  ASSERT_TRUE(inside.hit);
  EXPECT_EQ(inside.h.coverage, 1.0f);
  EXPECT_FALSE(probe(set, Ray{{0, 0.21f, 0}, {0, 0, 1}}, none).hit);
}

}  // namespace
}  // namespace darc

namespace darc {
namespace {

// A segment seen nearly end-on that bends: on the screen a stub a fraction of its width long
// whose ends point off its chord. As a band through its closest point, left uncut at its joints
// (they turn on the screen), it covered a stripe across the footprint; its coverage is now what
// the exact intersector's rays through the footprint see (the scalp's crown).
TEST(CurveDistance, StubSeenEndOnCoversWhatTheExactIntersectorSees) {
  // Mostly along the ray (+z), 0.3 long on the screen against a width of 1: a joint at each end.
  const std::array<Vec3f, 4> points{Vec3f{-0.15f, 0.0f, 4.0f}, Vec3f{-0.05f, 0.12f, 5.0f},
                                    Vec3f{0.05f, 0.12f, 6.0f}, Vec3f{0.15f, 0.0f, 7.0f}};
  CurveSet set;
  set.add_segment(points, {1.0f, 1.0f, 1.0f, 1.0f}, 0, 0);
  SegmentEnds joints;
  joints.cut_joints = true;  // the segment is between two others of its strand
  for (const Vec3f origin : {Vec3f{0, 0, 0}, Vec3f{0.5f, 0.2f, 0}, Vec3f{-0.6f, -0.5f, 0}}) {
    const Ray ray{origin, {0, 0, 1}};
    const RayFootprint fp = orthographic(1.5f);
    CurveFragmentHit h;
    ASSERT_TRUE(intersect_segment_distance(set, 0, ray, fp, CoverageModel::Square, joints, h, true));
    // The exact intersector on a 64 x 64 grid of parallel rays through the footprint.
    int inside = 0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) {
        const float u = (float(i) + 0.5f) / 64.0f - 0.5f, v = (float(j) + 0.5f) / 64.0f - 0.5f;
        CurveHit exact;
        inside += intersect_segment(set, 0, Ray{origin + Vec3f{1.5f * u, 1.5f * v, 0}, {0, 0, 1}}, exact);
      }
    const float expected = float(inside) / (64.0f * 64.0f);
    EXPECT_NEAR(h.coverage, expected, 0.03f) << "ray from " << origin.x << " " << origin.y;
    EXPECT_LE(float(mask_count(h.mask)) / 64.0f, expected + 0.35f) << "the mask stays around the stub";
  }
}

}  // namespace
}  // namespace darc
