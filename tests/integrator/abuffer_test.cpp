// The A-buffer against analytic compositing: per-strand dedupe, finished strands, insertion
// order, the cap merge, transmittance and colour for known coverages.
#include "integrator/abuffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace darc {
namespace {

// Shades every fragment with an opaque colour that depends on its primitive, so that the
// compositing order shows in the result.
ShadedFragment shade_by_primitive(const Fragment& f) {
  float p = float(f.primitive);
  Vec3f c{0.1f + 0.8f * std::fmod(p * 0.37f, 1.0f), 0.2f + 0.7f * std::fmod(p * 0.61f, 1.0f), 0.5f};
  return {c, Vec3f{1, 1, 1}};
}

Fragment strand_fragment(uint32_t strand, float t, float coverage) {
  Fragment f;
  f.t = t;
  f.coverage = coverage;
  f.strand = strand;
  f.primitive = strand;
  return f;
}

// Front-to-back compositing of fragments, reference for the A-buffer.
struct Composite {
  Vec3f color, transmittance{1, 1, 1};
};
Composite composite_all(std::vector<Fragment> fragments) {
  std::sort(fragments.begin(), fragments.end(), [](const Fragment& a, const Fragment& b) { return a.t < b.t; });
  Composite c;
  for (const Fragment& f : fragments) {
    ShadedFragment s = shade_by_primitive(f);
    c.color += mul(c.transmittance, s.Ci * f.coverage);
    c.transmittance = mul(c.transmittance, Vec3f{1, 1, 1} - s.Oi * f.coverage);
  }
  return c;
}

void expect_near(const Vec3f& a, const Vec3f& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(ABuffer, TransmittanceAndColourForKnownCoverages) {
  ABuffer ab;
  auto white = [](const Fragment&) { return ShadedFragment{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}}; };
  ab.add(strand_fragment(1, 2.0f, 0.5f), white);
  ab.add(strand_fragment(2, 1.0f, 0.25f), white);
  ab.composite_until(10.0f, white);
  // 1 - (1 - 0.25)(1 - 0.5) = 0.625, in every channel; colour = alpha for white opaque strands.
  expect_near(ab.transmittance(), Vec3f{0.375f, 0.375f, 0.375f}, 1e-6f);
  expect_near(ab.color(), Vec3f{0.625f, 0.625f, 0.625f}, 1e-6f);
  // Colour is premultiplied: a red strand in front of a blue one.
  ABuffer rb;
  auto red_blue = [](const Fragment& f) {
    return ShadedFragment{f.strand == 1 ? Vec3f{1, 0, 0} : Vec3f{0, 0, 1}, Vec3f{1, 1, 1}};
  };
  rb.add(strand_fragment(2, 3.0f, 1.0f), red_blue);
  rb.add(strand_fragment(1, 1.0f, 0.4f), red_blue);
  rb.composite_until(10.0f, red_blue);
  expect_near(rb.color(), Vec3f{0.4f, 0.0f, 0.6f}, 1e-6f);
  expect_near(rb.transmittance(), Vec3f{0, 0, 0}, 1e-6f);
}

// Masks of the left and right halves of the footprint (columns 0-3 and 4-7 of the 8x8 points).
constexpr CoverageMask kLeftHalf = 0x0F0F0F0F0F0F0F0Full;
constexpr CoverageMask kRightHalf = ~kLeftHalf;

Fragment piece(uint32_t strand, float t, float coverage, CoverageMask mask) {
  Fragment f = strand_fragment(strand, t, coverage);
  f.mask = mask;
  return f;
}

TEST(ABuffer, PiecesOfAStrandAddUpThroughTheirMasks) {
  auto white = [](const Fragment&) { return ShadedFragment{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}}; };
  // Side by side (two segments of a strand meeting at a joint in the footprint): they add up.
  ABuffer side;
  side.add(piece(7, 2.0f, 0.3f, kLeftHalf), white);
  side.add(piece(7, 2.1f, 0.3f, kRightHalf), white);
  side.composite_until(100.0f, white);
  EXPECT_EQ(side.fragments_added(), 1u) << "one fragment per strand per ray";
  expect_near(side.transmittance(), Vec3f{0.4f, 0.4f, 0.4f}, 1e-6f);
  // Over each other (a kink): the second piece adds nothing new.
  ABuffer over;
  over.add(piece(7, 2.0f, 0.3f, kLeftHalf), white);
  over.add(piece(7, 2.1f, 0.2f, kLeftHalf), white);
  over.composite_until(100.0f, white);
  expect_near(over.transmittance(), Vec3f{0.7f, 0.7f, 0.7f}, 1e-6f);
  // Without masks (all points) pieces simply add, up to full coverage.
  ABuffer scalar;
  scalar.add(strand_fragment(7, 2.0f, 0.3f), white);
  scalar.add(strand_fragment(7, 2.5f, 0.6f), white);
  scalar.add(strand_fragment(7, 1.5f, 0.2f), white);
  scalar.composite_until(100.0f, white);
  EXPECT_EQ(scalar.fragments_added(), 1u);
  expect_near(scalar.transmittance(), Vec3f{0, 0, 0}, 1e-6f);
}

TEST(ABuffer, APieceArrivingAfterItsStrandWasCompositedOnlyFillsNewPoints) {
  auto white = [](const Fragment&) { return ShadedFragment{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}}; };
  ABuffer ab;
  ab.add(piece(3, 1.0f, 0.5f, kLeftHalf), white);
  ab.composite_until(1.5f, white);
  // Another segment of the strand, on the same points: they are already opaque.
  ab.add(piece(3, 2.0f, 0.5f, kLeftHalf), white);
  ab.composite_until(100.0f, white);
  expect_near(ab.transmittance(), Vec3f{0.5f, 0.5f, 0.5f}, 1e-6f);
  // On the other half: it covers it.
  ab.add(piece(3, 3.0f, 0.5f, kRightHalf), white);
  ab.composite_until(100.0f, white);
  expect_near(ab.transmittance(), Vec3f{0, 0, 0}, 1e-6f);
  // Surfaces (no strand) are never merged.
  ABuffer surfaces;
  auto grey = [](const Fragment&) { return ShadedFragment{Vec3f{0.5f, 0.5f, 0.5f}, Vec3f{0.5f, 0.5f, 0.5f}}; };
  surfaces.add(Fragment{1.0f, 1.0f, kNoStrand, 0, 0, false, {}, {}}, grey);
  surfaces.add(Fragment{2.0f, 1.0f, kNoStrand, 1, 0, false, {}, {}}, grey);
  surfaces.composite_until(100.0f, grey);
  expect_near(surfaces.transmittance(), Vec3f{0.25f, 0.25f, 0.25f}, 1e-6f);
}

std::vector<Fragment> distinct_strands(int n, std::mt19937& rng) {
  std::uniform_real_distribution<float> t(1.0f, 50.0f), coverage(0.01f, 0.2f);
  std::vector<Fragment> f;
  for (int i = 0; i < n; ++i) f.push_back(strand_fragment(uint32_t(i), t(rng), coverage(rng)));
  return f;
}

TEST(ABuffer, CompositingIsIndependentOfInsertionOrder) {
  std::mt19937 rng(11);
  std::vector<Fragment> fragments = distinct_strands(40, rng);
  ABuffer first;
  for (const Fragment& f : fragments) first.add(f, shade_by_primitive);
  first.composite_until(25.0f, shade_by_primitive);
  first.composite_until(1e9f, shade_by_primitive);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(fragments.begin(), fragments.end(), rng);
    ABuffer ab;
    for (const Fragment& f : fragments) ab.add(f, shade_by_primitive);
    ab.composite_until(1e9f, shade_by_primitive);
    EXPECT_EQ(ab.color(), first.color());  // bitwise: same sort, same sums
    EXPECT_EQ(ab.transmittance(), first.transmittance());
  }
  Composite expected = composite_all(fragments);
  expect_near(first.color(), expected.color, 1e-5f);
  expect_near(first.transmittance(), expected.transmittance, 1e-5f);
}

// Fragments arriving front to back (as traversal delivers them) or back to front: the merged
// pair is always adjacent in depth, so the merge is exact up to rounding.
TEST(ABuffer, CapMergeMatchesCompositingEverything) {
  std::mt19937 rng(5);
  const int n = int(kMaxFragments) * 3;
  std::vector<Fragment> fragments = distinct_strands(n, rng);
  Composite expected = composite_all(fragments);
  std::sort(fragments.begin(), fragments.end(), [](const Fragment& a, const Fragment& b) { return a.t < b.t; });
  for (bool reversed : {false, true}) {
    if (reversed) std::reverse(fragments.begin(), fragments.end());
    ABuffer ab;
    for (const Fragment& f : fragments) ab.add(f, shade_by_primitive);
    EXPECT_LE(ab.peak_length(), kMaxFragments + 1);
    ab.composite_until(1e9f, shade_by_primitive);
    expect_near(ab.color(), expected.color, 1e-5f);
    expect_near(ab.transmittance(), expected.transmittance, 1e-5f);
  }
}

// In arbitrary order a fragment can arrive between two already merged ones; the merge then
// composites it in the wrong place. A bounded list cannot avoid that (Yu et al.'s k-buffer
// has the same limit); with coverages of 1-20% the error stays small.
TEST(ABuffer, CapMergeInArbitraryOrderStaysClose) {
  std::mt19937 rng(9);
  std::vector<Fragment> fragments = distinct_strands(int(kMaxFragments) * 3, rng);
  Composite expected = composite_all(fragments);
  ABuffer ab;
  for (const Fragment& f : fragments) ab.add(f, shade_by_primitive);
  ab.composite_until(1e9f, shade_by_primitive);
  expect_near(ab.transmittance(), expected.transmittance, 1e-5f);  // a product: order-free
  expect_near(ab.color(), expected.color, 0.05f);
}

// A dense clump seen grazing (hair at a head's silhouette): hundreds of strands, far more than
// the list holds, all over the same few points of the footprint. Merging them as scalar
// coverages treats them as independent and fills the footprint (1 - (1 - c)^n); merged point by
// point they cover what their masks cover, in any insertion order.
TEST(ABuffer, CapMergeKeepsWhereTheFragmentsLie) {
  const CoverageMask corner = 0x0303;  // four points in a corner
  auto white = [](const Fragment&) { return ShadedFragment{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}}; };
  std::mt19937 rng(11);
  std::vector<Fragment> fragments;
  for (int i = 0; i < int(kMaxFragments) * 5; ++i) {
    Fragment f = strand_fragment(uint32_t(i), 1.0f + 0.01f * float(i), 2.0f / 64.0f);
    f.mask = corner;
    fragments.push_back(f);
  }
  for (int trial = 0; trial < 3; ++trial) {
    if (trial == 2) std::shuffle(fragments.begin(), fragments.end(), rng);
    if (trial == 1) std::reverse(fragments.begin(), fragments.end());
    ABuffer ab;
    for (const Fragment& f : fragments) ab.add(f, white);
    ASSERT_GT(ab.fragments_merged(), 0u);
    ab.composite_until(1e9f, white);
    // Each point of the corner is behind 320 layers of opacity 0.5: closed; the rest is clear.
    expect_near(ab.transmittance(), Vec3f{60.0f, 60.0f, 60.0f} / 64.0f, 1e-5f);
    expect_near(ab.color(), Vec3f{4.0f, 4.0f, 4.0f} / 64.0f, 1e-5f);
  }
}

// Fragments whose coverage is larger than their mask holds (a mask rounds its count): the excess
// stays around the mask. Spread over the whole footprint, a few hundred such fragments of a
// clump fill it.
TEST(ABuffer, CoverageBeyondTheMaskStaysNearIt) {
  const CoverageMask corner = 1;  // the first point
  auto white = [](const Fragment&) { return ShadedFragment{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}}; };
  ABuffer ab;
  for (int i = 0; i < 200; ++i) {
    Fragment f = strand_fragment(uint32_t(i), 1.0f + 0.01f * float(i), 1.4f / 64.0f);
    f.mask = corner;
    ab.add(f, white);
    ab.composite_until(1e9f, white);
  }
  // The corner point and its three neighbours at most.
  EXPECT_GE(ab.transmittance().x, 60.0f / 64.0f - 1e-5f);
  EXPECT_LT(ab.transmittance().x, 63.0f / 64.0f);
}

// Shadow rays composite whatever they hold at every step: transmittance is a product, so it
// matches compositing in depth order; pieces of a surface layer not yet final wait (more pieces
// of their mesh may come and must be summed with them first).
TEST(ABuffer, TransmittanceIsTheSameInAnyOrder) {
  std::mt19937 rng(17);
  std::vector<Fragment> fragments = distinct_strands(int(kMaxFragments) / 2, rng);
  for (size_t i = 0; i < fragments.size(); ++i) fragments[i].mask = CoverageMask{0xff} << (8 * (i % 8));
  auto grey = [](const Fragment& f) {
    const float o = 0.2f + 0.1f * float(f.primitive % 7);
    return ShadedFragment{Vec3f{}, Vec3f{o, o, o}};
  };
  ABuffer ordered;
  for (const Fragment& f : fragments) ordered.add(f, grey);
  ordered.composite_until(1e9f, grey);
  ABuffer any_order;
  for (size_t i = 0; i < fragments.size(); ++i) {
    any_order.add(fragments[i], grey);
    if (i % 5 == 4) any_order.composite_for_transmittance(0.0f, grey);
  }
  any_order.composite_for_transmittance(1e9f, grey);
  expect_near(any_order.transmittance(), ordered.transmittance(), 1e-5f);
  // A layer piece beyond t_final stays pending until it is final.
  ABuffer layered;
  Fragment piece;
  piece.t = 5.0f;
  piece.coverage = 0.5f;
  piece.layer = 3;
  piece.t_near = piece.t_far = 5.0f;
  layered.add(piece, grey);
  EXPECT_EQ(layered.composite_for_transmittance(4.0f, grey), 0u);
  EXPECT_EQ(layered.composite_for_transmittance(6.0f, grey), 1u);
}

// Two pieces of one mesh sharing an edge across the footprint, the second met after the walk
// passed the first's sort depth but not its farthest: they still add up to the whole footprint,
// as when both came first (a layer composited at its sort depth left its neighbour to be
// composited alone: the Aqsis vase lost 5 % of a pixel's alpha along such edges, depending on
// the order the walk met the pieces in).
TEST(ABuffer, APieceOfALayerMetAfterItsNeighboursSortDepthStillJoinsIt) {
  auto grey = [](const Fragment&) { return ShadedFragment{Vec3f{0.5f, 0.5f, 0.5f}, Vec3f{1, 1, 1}}; };
  Fragment left;
  left.layer = 2;
  left.primitive = 1;
  left.coverage = 0.95f;
  left.mask = ~CoverageMask{0} >> 4;  // all but four points
  left.t = 5.0f, left.t_near = 4.9f, left.t_far = 5.2f;
  Fragment right = left;
  right.primitive = 2;
  right.coverage = 0.05f;
  right.mask = ~left.mask;
  right.t = 5.15f, right.t_near = 5.2f, right.t_far = 5.25f;
  for (float between : {5.1f, 5.19f}) {
    ABuffer ab;
    ab.add(left, grey);
    ab.composite_until(between, grey);  // the walk has passed left.t, not left.t_far
    ab.add(right, grey);
    ab.composite_until(std::numeric_limits<float>::infinity(), grey);
    expect_near(ab.transmittance(), Vec3f{0, 0, 0}, 1e-5f);
    expect_near(ab.color(), Vec3f{0.5f, 0.5f, 0.5f}, 1e-5f);
  }
}

// Pieces of one mesh over each other (a fold at its outline, a lid over its pot) share mask
// points: they are not one layer but composited in depth order, the near one seen.
TEST(ABuffer, PiecesOfALayerOverEachOtherStayApart) {
  auto by_primitive = [](const Fragment& f) {
    return ShadedFragment{f.primitive == 1 ? Vec3f{1, 1, 1} : Vec3f{0, 0, 0}, Vec3f{1, 1, 1}};
  };
  Fragment near;
  near.layer = 2;
  near.primitive = 1;
  near.coverage = 1.0f;
  near.mask = kFullMask;
  near.t = 5.0f, near.t_near = 4.95f, near.t_far = 5.05f;
  Fragment far = near;
  far.primitive = 2;
  far.t = 5.1f, far.t_near = 5.05f, far.t_far = 5.15f;  // touching depth ranges
  for (bool far_first : {false, true}) {
    ABuffer ab;
    ab.add(far_first ? far : near, by_primitive);
    ab.add(far_first ? near : far, by_primitive);
    ab.composite_until(std::numeric_limits<float>::infinity(), by_primitive);
    expect_near(ab.color(), Vec3f{1, 1, 1}, 1e-5f);
  }
}

TEST(ABuffer, EqualCoveragePiecesShadeTheOneNearestTheRay) {
  // Two pieces of one strand that both cover the whole footprint: the shading point is the
  // piece passing nearer the ray centre, whichever came first.
  for (bool near_first : {true, false}) {
    ABuffer ab;
    Fragment near = strand_fragment(1, 2.0f, 1.0f), far = near;
    near.primitive = 10;
    near.distance = 0.1f;
    far.primitive = 20;
    far.distance = 0.4f;
    uint32_t shaded = 0;
    auto record = [&](const Fragment& f) {
      shaded = f.primitive;
      return ShadedFragment{Vec3f{1, 1, 1}, Vec3f{1, 1, 1}};
    };
    ab.add(near_first ? near : far, record);
    ab.add(near_first ? far : near, record);
    ab.composite_until(10.0f, record);
    EXPECT_EQ(shaded, 10u) << (near_first ? "near first" : "far first");
  }
}

TEST(ABuffer, FragmentsAtEqualDepthShareWhereTheyOverlap) {
  // Two opaque strands over the same half of the footprint at the same depth: each in front
  // half the time, so their mean colour over that half, in either insertion order.
  auto by_strand = [](const Fragment& f) {
    return ShadedFragment{f.strand == 1 ? Vec3f{1, 0, 0} : Vec3f{0, 0, 1}, Vec3f{1, 1, 1}};
  };
  const CoverageMask half = 0x00000000ffffffffull;
  for (bool red_first : {true, false}) {
    ABuffer ab;
    Fragment red = strand_fragment(1, 3.0f, 0.5f), blue = strand_fragment(2, 3.0f, 0.5f);
    red.mask = blue.mask = half;
    ab.add(red_first ? red : blue, by_strand);
    ab.add(red_first ? blue : red, by_strand);
    ab.composite_until(10.0f, by_strand);
    expect_near(ab.color(), Vec3f{0.25f, 0.0f, 0.25f}, 1e-6f);
    expect_near(ab.transmittance(), Vec3f{0.5f, 0.5f, 0.5f}, 1e-6f);
  }
  // Apart in depth by more than kEqualDepthFraction, the nearer one hides the other.
  ABuffer ab;
  Fragment red = strand_fragment(1, 3.0f, 0.5f), blue = strand_fragment(2, 3.0f * (1 + 1e-4f), 0.5f);
  red.mask = blue.mask = half;
  ab.add(blue, by_strand);
  ab.add(red, by_strand);
  ab.composite_until(10.0f, by_strand);
  expect_near(ab.color(), Vec3f{0.5f, 0.0f, 0.0f}, 1e-6f);
}

TEST(ABuffer, ClearResetsEverything) {
  ABuffer ab;
  ab.add(strand_fragment(1, 1.0f, 1.0f), shade_by_primitive);
  ab.composite_until(5.0f, shade_by_primitive);
  ab.clear();
  ab.add(strand_fragment(1, 1.0f, 0.5f), shade_by_primitive);
  ab.composite_until(5.0f, shade_by_primitive);
  expect_near(ab.transmittance(), Vec3f{0.5f, 0.5f, 0.5f}, 1e-6f);
  EXPECT_EQ(ab.fragments_added(), 1u);
}

}  // namespace
}  // namespace darc
