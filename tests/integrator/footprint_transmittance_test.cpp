// The footprint transmittance query (the walk and A-buffer of camera rays, opacity only) against
// analytic values: strands stacked in depth over the same part of the footprint, strands side by
// side, a skipped strand, an opaque surface behind.
#include "integrator/distance_hider.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "shading/scene_shading.h"
#include "support/scenes_from_rib.h"

namespace darc {
namespace {

// Float rounding of the per-point composite and of the band coverage.
constexpr float kTolerance = 1e-4f;

Scene build_scene(const std::string& world) {
  return test::build_scene("Projection \"orthographic\"\nWorldBegin\n" + world + "WorldEnd\n");
}

// A straight strand along x at height y and depth z.
std::string strand(float y, float z, float width, float opacity) {
  std::ostringstream s;
  s << "AttributeBegin\nOpacity [" << opacity << " " << opacity << " " << opacity << "]\n"
    << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [-3 " << y << " " << z << "  3 " << y << " " << z
    << "] \"constantwidth\" [" << width << "]\nAttributeEnd\n";
  return s.str();
}

// The transmittance of footprint fp along ray.
Vec3f transmittance_along(const Scene& scene, const Ray& ray, const RayFootprint& fp, uint32_t skip_strand = kNoStrand,
                          DistanceHiderSettings settings = {}) {
  Diagnostics diag([](const Diagnostic&) {});
  SceneShading shading(scene, diag);
  Tracer tracer(scene);
  HiderContext base{scene, shading, tracer, 0, 1, 1};
  DistanceContext ctx = make_distance_context(base, settings);
  RayCounters counters;
  RayScratchStack scratch(scene.accel);
  return trace_footprint_transmittance(ctx, ray, fp, counters, scratch.at(0), skip_strand);
}

// The transmittance seen along +z from (0, 0, -1) with a 1 x 1 footprint (orthographic).
Vec3f transmittance(const Scene& scene, uint32_t skip_strand = kNoStrand, DistanceHiderSettings settings = {},
                    Vec3f origin = {0, 0, -1}) {
  RayFootprint fp;
  fp.dox = Vec3f{1, 0, 0};
  fp.doy = Vec3f{0, 1, 0};
  return transmittance_along(scene, Ray{origin, {0, 0, 1}}, fp, skip_strand, settings);
}

// A shadow ray's receiving patch leans along the ray (a strand's band runs along the strand,
// a light off its side): sub-ray (u, v) starts at (u, v, 0.8 u) and runs along +z. A strand
// along y of width w at x_A, depth z_A is met by the sub-rays |u - x_A| <= w/2 that start
// before it, 0.8 u < z_A, whatever the centre ray's start (z = 0) says.
Vec3f leaning_patch_transmittance(float x_a, float z_a, float width) {
  std::ostringstream s;
  s << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [" << x_a << " -3 " << z_a << "  " << x_a << " 3 " << z_a
    << "] \"constantwidth\" [" << width << "]\n";
  RayFootprint fp;
  fp.dox = Vec3f{1, 0, 0.8f};
  fp.doy = Vec3f{0, 1, 0};
  fp.form = FootprintForm::Parallel;
  return transmittance_along(build_scene(s.str()), Ray{{0, 0, 0}, {0, 0, 1}}, fp);
}

TEST(FootprintTransmittance, ALeaningPatchsNearSideMeetsAStrandBehindItsCentre) {
  // Behind the centre's start (z_A = -0.15 < 0), but the sub-rays at u in [-0.35, -0.25] start
  // at depth <= -0.2: they meet it (the head-hair's clumps: shadow rays from a strand missed the
  // neighbours beside its band).
  EXPECT_NEAR(leaning_patch_transmittance(-0.3f, -0.15f, 0.1f).x, 0.9f, 0.02f);
}

TEST(FootprintTransmittance, ALeaningPatchsFarSideStartsPastAStrandAheadOfItsCentre) {
  // Ahead of the centre (z_A = 0.15), but the sub-rays at u in [0.25, 0.35] start at depth
  // >= 0.2, past it: nothing meets it.
  EXPECT_NEAR(leaning_patch_transmittance(0.3f, 0.15f, 0.1f).x, 1.0f, 1e-6f);
  // Half of them start before it when it sits at the band's middle depth (0.8 * 0.3 = 0.24).
  EXPECT_NEAR(leaning_patch_transmittance(0.3f, 0.24f, 0.1f).x, 0.95f, 0.02f);
}

TEST(FootprintTransmittance, StrandsStackedInDepthOccludeTheSamePoints) {
  // k strands of coverage c = 0.25 and opacity o over the same quarter of the footprint: that
  // quarter transmits (1 - o)^k, the rest everything.
  const float c = 0.25f, o = 0.4f;
  for (int k = 1; k <= 4; ++k) {
    std::string world;
    for (int i = 0; i < k; ++i) world += strand(0.0f, 2.0f + float(i), c, o);
    Vec3f t = transmittance(build_scene(world));
    float expected = 1.0f - c + c * std::pow(1.0f - o, float(k));
    EXPECT_NEAR(t.x, expected, kTolerance) << k << " strands";
    EXPECT_NEAR(t.y, expected, kTolerance);
  }
}

// A shadow ray through dense hair must stop once it is blocked. Strands that run almost along
// the ray have boxes spanning every depth, so a walk that composites only what it has passed in
// depth (as camera rays must, for colour) learns nothing until it has visited every strand;
// transmittance is a product, so the shadow ray composites what it holds at every step instead.
TEST(FootprintTransmittance, ShadowRayStopsOnceBlockedWhateverTheDepthOrder) {
  const int n = 200;
  std::string world = "Opacity [0.5 0.5 0.5]\n";
  for (int i = 0; i < n; ++i) {
    // Crosses the ray (x = 0) at z = 501 + i, covering the whole footprint (width 2).
    std::ostringstream s;
    s << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [-5 0 " << 1 + i << "  5 0 " << 1001 + i
      << "] \"constantwidth\" [2]\n";
    world += s.str();
  }
  const Scene scene = build_scene(world);
  Diagnostics diag([](const Diagnostic&) {});
  SceneShading shading(scene, diag);
  Tracer tracer(scene);
  HiderContext base{scene, shading, tracer, 0, 1, 1};
  DistanceContext ctx = make_distance_context(base, {});
  RayFootprint fp;
  fp.dox = Vec3f{1, 0, 0};
  fp.doy = Vec3f{0, 1, 0};
  Ray ray{{0, 0, -1}, {0, 0, 1}};
  RayCounters counters;
  RayScratchStack scratch(scene.accel);
  const Vec3f t = trace_footprint_transmittance(ctx, ray, fp, counters, scratch.at(0), kNoStrand);
  EXPECT_LT(max_component(t), kDistanceMinTransmittance);
  EXPECT_EQ(counters.rays_terminated_early, 1u);
  // Ten strands of opacity 0.5 leave 1e-3; the walk tests them in batches of a few leaves.
  EXPECT_LT(counters.segment_tests, uint64_t(n / 4)) << "the walk went on through the blocked hair";
}

// A clump: a hundred strands over the same part of the footprint, each slightly wider than a
// whole number of mask points (5.2 points). They cover what one covers. With masks of the
// nearest whole count (5 points) each left 0.2 of a point beside its mask, and a hundred such
// remainders filled the points around it: transmittance 0.76 where one strand leaves 0.92.
TEST(FootprintTransmittance, ACoincidentClumpCoversWhatOneStrandCovers) {
  const float c = 5.2f / 64.0f;
  std::string world;
  for (int i = 0; i < 100; ++i) world += strand(0.0f, 2.0f + 0.05f * float(i), c, 1.0f);
  const Vec3f t = transmittance(build_scene(world));
  EXPECT_NEAR(t.x, 1.0f - c, 1.5f / 64.0f);
}

TEST(FootprintTransmittance, StrandsSideBySideAddUp) {
  // Four strands of width 0.25 tiling the footprint, each at its own depth: 1 - 4 * c * o.
  const float c = 0.25f, o = 0.4f;
  std::string world;
  for (int i = 0; i < 4; ++i) world += strand(-0.375f + 0.25f * float(i), 2.0f + float(i), c, o);
  Vec3f t = transmittance(build_scene(world));
  EXPECT_NEAR(t.x, 1.0f - 4.0f * c * o, 0.02f);  // the mask points place each band to 1/8
}

// k parallel strands of coverage c and opacity o, separated in depth, at positions across the
// footprint that nothing correlates: the seed's scalar composite gives (1 - c o)^k (each strand
// takes c o of what is left). The masks instead see where each strand lies: stacked strands and
// strands side by side are the two tests above.
TEST(FootprintTransmittance, SeparatedUncorrelatedStrandsTransmitTheProductOfTheirClearances) {
  const float c = 0.125f, o = 0.5f;
  DistanceHiderSettings scalar;
  scalar.coverage_masks = false;
  for (int k = 1; k <= 5; ++k) {
    std::string world;
    for (int i = 0; i < k; ++i) world += strand(-0.3f + 0.15f * float(i), 2.0f + float(i), c, o);
    Vec3f t = transmittance(build_scene(world), kNoStrand, scalar);
    EXPECT_NEAR(t.x, std::pow(1.0f - c * o, float(k)), kTolerance) << k << " strands";
  }
}

TEST(FootprintTransmittance, TheSkippedStrandCastsNothing) {
  Scene scene = build_scene(strand(0.0f, 2.0f, 0.5f, 1.0f) + strand(0.0f, 3.0f, 0.25f, 1.0f));
  ASSERT_EQ(scene.curves.size(), 2u);
  EXPECT_NEAR(transmittance(scene).x, 0.5f, kTolerance);  // the wide one hides the narrow one
  EXPECT_NEAR(transmittance(scene, scene.curves.strand_id[0]).x, 0.75f, kTolerance);
  EXPECT_NEAR(transmittance(scene, scene.curves.strand_id[1]).x, 0.5f, kTolerance);
}

TEST(FootprintTransmittance, AnOpaqueSurfaceBlocksEverything) {
  Scene scene = build_scene(strand(0.0f, 2.0f, 0.25f, 0.5f) + "Polygon \"P\" [-5 -5 4  5 -5 4  5 5 4  -5 5 4]\n");
  EXPECT_NEAR(transmittance(scene).x, 0.0f, kTolerance);
}

}  // namespace
}  // namespace darc
