// The interaction of a footprint with a strand: the patch its rays leave from (the band of the
// footprint that is the strand).
#include "core/scene/interaction.h"

#include <gtest/gtest.h>

#include <string>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

// One straight strand along x through the origin, of width `width`, seen along +z.
Scene strand_scene(float width) {
  return test::build_scene("Projection \"orthographic\"\nWorldBegin\nCurves \"linear\" [2] \"nonperiodic\" \"P\" "
                           "[-3 0 0  3 0 0] \"constantwidth\" [" +
                           std::to_string(width) + "]\nWorldEnd\n");
}

Interaction strand_patch(const Scene& scene, float footprint_side) {
  RayFootprint fp;
  fp.dox = Vec3f{footprint_side, 0, 0};
  fp.doy = Vec3f{0, footprint_side, 0};
  fp.form = FootprintForm::Parallel;
  const Ray ray{{0, 0, -1}, {0, 0, 1}};
  return make_interaction(scene, 0, ray, 1.0f, 0.5f, &fp);
}

TEST(StrandPatch, IsTheStrandsBandAcrossTheFootprint) {
  // A footprint 4 widths wide: the band is as wide as the strand and as long as the footprint.
  const Scene scene = strand_scene(0.25f);
  const Interaction at = strand_patch(scene, 1.0f);
  EXPECT_NEAR(length(at.dPdy), 0.25f, 1e-5f);
  EXPECT_NEAR(length(at.dPdx), 1.0f, 1e-5f);
  EXPECT_NEAR(std::abs(at.dPdx.x), 1.0f, 1e-5f);  // along the strand
}

TEST(StrandPatch, IsAtMostEightWidthsLongInAWideFootprint) {
  // A footprint 50 widths wide (a thumbnail's): a band as long as the footprint would meet every
  // strand crossing it; the patch is 8 widths of the strand around where it is seen.
  const Scene scene = strand_scene(0.02f);
  const Interaction at = strand_patch(scene, 1.0f);
  EXPECT_NEAR(length(at.dPdy), 0.02f, 1e-6f);
  EXPECT_NEAR(length(at.dPdx), 8 * 0.02f, 1e-5f);
  EXPECT_NEAR(std::abs(at.dPdx.x), 8 * 0.02f, 1e-5f);
}

}  // namespace
}  // namespace darc
