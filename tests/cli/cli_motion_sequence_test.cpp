// End-to-end: a swinging tuft rendered as a sequence with motion blur (each frame a MotionBegin
// block of the strands at its start and end, Shutter 0 1). A frame rendered alone (--frames) is
// bitwise the same frame of the whole run, with either hider, and the blur changes the image.
#include <cmath>
#include <random>

#include "support/cubic_strands.h"
#include "support/darc_command.h"
#include "support/image_files.h"

namespace darc::test {
namespace {

// 200 b-spline strands of 6 points rising from y = -1, bent sideways by `sway` times the square
// of their height.
std::string tuft(float sway) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  float x = 0, z = 0;
  const StrandPoint point = [&](int, int v) {
    if (v == 0) {
      x = 0.6f * u(rng);
      z = 0.6f * u(rng);
    }
    const float h = 0.3f * float(v);
    return Vec3f{x + 0.03f * float(v) * u(rng) + sway * h * h, -1.0f + h, z};
  };
  return cubic_strands(200, 6, point, 0.02f);
}

std::string swing(int frames, const std::string& shutter) {
  std::string rib = shutter + "\n";
  for (int f = 1; f <= frames; ++f)
    rib += "FrameBegin " + std::to_string(f) + "\nDisplay \"swing.#.exr\" \"file\" \"rgba\"\nFormat 48 36 1\n"
           "PixelSamples 2 2\nProjection \"perspective\" \"fov\" [40]\nTranslate 0 0 4\nWorldBegin\n"
           "LightSource \"distantlight\" 1 \"from\" [0 2 -2]\nSurface \"hair\"\nBasis \"b-spline\" 1 \"b-spline\" 1\n"
           "MotionBegin [0 1]\n" +
           tuft(0.5f * std::sin(0.8f * float(f))) + tuft(0.5f * std::sin(0.8f * float(f + 1))) +
           "MotionEnd\nWorldEnd\nFrameEnd\n";
  return rib;
}

Pixels pixels(const fs::path& p) {
  Pixels out;
  EXPECT_TRUE(read_image(p, out)) << p;
  return out;
}

TEST(CliMotionSequence, AFrameRenderedAloneIsItsFrameOfTheSequence) {
  ScratchDir dir("motion-sequence");
  write_file(dir / "swing.rib", swing(4, "Shutter 0 1"));
  for (const char* hider : {"distance", "stochastic"}) {
    ASSERT_EQ(run_darc(dir.path(), std::string("--hider ") + hider + " swing.rib").exit_code, 0);
    std::vector<Pixels> run;
    for (int f = 1; f <= 4; ++f) run.push_back(pixels(dir / ("swing." + std::to_string(f) + ".exr")));
    for (int f : {2, 4}) {
      fs::remove(dir / ("swing." + std::to_string(f) + ".exr"));
      ASSERT_EQ(run_darc(dir.path(), std::string("--hider ") + hider + " --threads 2 --frames " + std::to_string(f) +
                                          " swing.rib")
                    .exit_code,
                0);
      EXPECT_TRUE(pixels(dir / ("swing." + std::to_string(f) + ".exr")).identical_to(run[size_t(f - 1)]))
          << hider << " frame " << f << " alone";
    }
    EXPECT_FALSE(run[0].identical_to(run[1])) << "the tuft swings";
  }
  // With the shutter closed, the frames are the strands at their start: another image.
  const Pixels blurred = pixels(dir / "swing.2.exr");
  write_file(dir / "swing.rib", swing(2, "Shutter 0 0"));
  ASSERT_EQ(run_darc(dir.path(), "--hider stochastic swing.rib").exit_code, 0);
  EXPECT_FALSE(pixels(dir / "swing.2.exr").identical_to(blurred));
}

}  // namespace
}  // namespace darc::test
