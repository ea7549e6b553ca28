// The same scene rendered with one and with two threads gives bitwise identical pixels, for
// both hiders (DESIGN.md: tiles share no mutable state and are merged in tile order).
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>

#include "support/render.h"
#include "support/test_frames.h"

namespace darc::test {

namespace {

// Larger than one render tile (32 px) in both directions, so two threads share the work.
constexpr int kWidth = 40, kHeight = 36;
constexpr int kStrands = 120;

// A tuft of curly semi-transparent strands in front of a sphere, lit.
std::string hair_scene() {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> root(-1.5f, 1.5f), bend(-0.6f, 0.6f), grey(0.2f, 0.9f);
  std::ostringstream w;
  w << "LightSource \"distantlight\" 1 \"from\" [0 0 0] \"to\" [1 -1 1]\nLightSource \"ambientlight\" 2\n"
    << "Surface \"plastic\"\nOpacity 0.7 0.7 0.7\n";
  for (int i = 0; i < kStrands; ++i) {
    float x = root(rng), z = 5 + root(rng);
    w << "Color " << grey(rng) << " " << grey(rng) << " 0.3\nCurves \"cubic\" [4] \"nonperiodic\" \"P\" [" << x
      << " -1.5 " << z << " " << x + bend(rng) << " -0.5 " << z + bend(rng) << " " << x + bend(rng) << " 0.5 "
      << z + bend(rng) << " " << x + bend(rng) << " 1.5 " << z << "] \"width\" [0.03 0.005]\n";
  }
  w << "Opacity 1 1 1\nColor 0.5 0.5 0.8\nTranslate 0 0 8\nSphere 2 -2 2 360\n";
  return perspective_frame(kWidth, kHeight, 2, 40, "", w.str());
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalPixels) {
  const std::string rib = hair_scene();
  for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic}) {
    SCOPED_TRACE(to_string(hider));
    RenderOptions options;
    options.hider = hider;
    options.threads = 1;
    RenderedFrame one = render_rib(rib, options);
    options.threads = 2;
    RenderedFrame two = render_rib(rib, options);
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    ASSERT_FALSE(one.image.pixels.empty());
    EXPECT_TRUE(one.image.pixels == two.image.pixels);  // bitwise
    EXPECT_GT(one.stats.counters.segment_tests, 0u);
  }
}

}  // namespace
}  // namespace darc::test
