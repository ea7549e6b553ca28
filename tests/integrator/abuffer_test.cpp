// The A-buffer against analytic compositing: per-strand dedupe, finished strands, insertion
// order, the cap merge, transmittance and colour for known coverages.
#include "integrator/abuffer.h"

#include <gtest/gtest.h>

#include <algorithm>
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

TEST(ABuffer, SameStrandTwiceKeepsTheLargerCoverage) {
  ABuffer ab;
  ab.add(strand_fragment(7, 2.0f, 0.3f), shade_by_primitive);
  ab.add(strand_fragment(7, 2.5f, 0.6f), shade_by_primitive);
  ab.add(strand_fragment(7, 1.5f, 0.2f), shade_by_primitive);
  ab.composite_until(100.0f, shade_by_primitive);
  EXPECT_EQ(ab.fragments_added(), 1u);
  expect_near(ab.transmittance(), Vec3f{0.4f, 0.4f, 0.4f}, 1e-6f);
  // Equal coverage: the nearer one wins (its t decides the compositing order).
  ABuffer tie;
  tie.add(strand_fragment(7, 2.0f, 0.5f), shade_by_primitive);
  tie.add(strand_fragment(7, 1.0f, 0.5f), shade_by_primitive);
  tie.add(strand_fragment(8, 1.5f, 1.0f), shade_by_primitive);
  tie.composite_until(100.0f, shade_by_primitive);
  Composite expected = composite_all({strand_fragment(7, 1.0f, 0.5f), strand_fragment(8, 1.5f, 1.0f)});
  expect_near(tie.color(), expected.color, 1e-6f);
}

TEST(ABuffer, FinishedStrandsAreIgnored) {
  ABuffer ab;
  ab.add(strand_fragment(3, 1.0f, 0.5f), shade_by_primitive);
  ab.composite_until(1.5f, shade_by_primitive);
  // The same strand seen again later (another segment or cell) must not add coverage.
  ab.add(strand_fragment(3, 2.0f, 0.9f), shade_by_primitive);
  ab.composite_until(100.0f, shade_by_primitive);
  EXPECT_EQ(ab.fragments_added(), 1u);
  expect_near(ab.transmittance(), Vec3f{0.5f, 0.5f, 0.5f}, 1e-6f);
  // Surfaces (no strand) are never deduplicated.
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

TEST(ABuffer, StrandMergedAtTheCapIsNotCountedTwice) {
  std::mt19937 rng(13);
  std::vector<Fragment> fragments = distinct_strands(int(kMaxFragments) + 8, rng);
  std::sort(fragments.begin(), fragments.end(), [](const Fragment& a, const Fragment& b) { return a.t < b.t; });
  Composite expected = composite_all(fragments);
  ABuffer ab;
  for (const Fragment& f : fragments) ab.add(f, shade_by_primitive);
  // The farthest strands were merged; another segment of each reports it again.
  for (size_t i = fragments.size() - 4; i < fragments.size(); ++i) ab.add(fragments[i], shade_by_primitive);
  ab.composite_until(1e9f, shade_by_primitive);
  expect_near(ab.transmittance(), expected.transmittance, 1e-5f);
  expect_near(ab.color(), expected.color, 1e-5f);
}

TEST(ABuffer, ClearResetsEverything) {
  ABuffer ab;
  ab.add(strand_fragment(1, 1.0f, 1.0f), shade_by_primitive);
  ab.composite_until(5.0f, shade_by_primitive);
  ab.clear();
  ab.add(strand_fragment(1, 1.0f, 0.5f), shade_by_primitive);  // no longer "finished"
  ab.composite_until(5.0f, shade_by_primitive);
  expect_near(ab.transmittance(), Vec3f{0.5f, 0.5f, 0.5f}, 1e-6f);
  EXPECT_EQ(ab.fragments_added(), 1u);
}

}  // namespace
}  // namespace darc
