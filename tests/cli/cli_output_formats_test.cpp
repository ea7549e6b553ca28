// End-to-end: what darc writes (the format follows the extension; the Display mode chooses the
// channels) and that no pixel is ever NaN or infinite, even for degenerate input.
#include <OpenImageIO/imageio.h>

#include <cmath>

#include "support/darc_command.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

// RI's "infinitely far" depth for pixels that see nothing (RI Spec 3.2, depth of the clipping
// far plane default); anything this large is a miss.
constexpr float kMissDepth = 1e30f;

OIIO::ImageSpec read_spec(const fs::path& p) {
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return OIIO::ImageSpec();
  OIIO::ImageSpec spec = in->spec();
  in->close();
  return spec;
}

// One run writes one frame per (file, mode) through its Display line.
struct FormatCase {
  std::string file, mode;
  int channels;
  OIIO::TypeDesc type;
};

TEST(CliOutputFormats, ExtensionChoosesTheFormatAndModeTheChannels) {
  ScratchDir dir("formats");
  const std::vector<FormatCase> cases = {
      {"rgba.exr", "rgba", 4, OIIO::TypeDesc::HALF},  {"rgb.exr", "rgb", 3, OIIO::TypeDesc::HALF},
      {"rgba.png", "rgba", 4, OIIO::TypeDesc::UINT8}, {"rgb.png", "rgb", 3, OIIO::TypeDesc::UINT8},
      {"rgba.tif", "rgba", 4, OIIO::TypeDesc::UINT8}, {"rgb.tif", "rgb", 3, OIIO::TypeDesc::UINT8},
      {"z.exr", "z", 1, OIIO::TypeDesc::FLOAT},       {"z.tif", "z", 1, OIIO::TypeDesc::FLOAT},
  };
  std::string rib;
  for (size_t i = 0; i < cases.size(); ++i) rib += tiny_frame_rib(int(i) + 1, cases[i].file, cases[i].mode);
  write_file(dir / "formats.rib", rib);
  RunResult r = run_darc(dir.path(), "formats.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const FormatCase& c : cases) {
    SCOPED_TRACE(c.file);
    OIIO::ImageSpec spec = read_spec(dir / c.file);
    EXPECT_EQ(spec.width, 32);
    EXPECT_EQ(spec.height, 24);
    EXPECT_EQ(spec.nchannels, c.channels);
    EXPECT_EQ(spec.format, c.type);
  }
  OIIO::ImageSpec exr = read_spec(dir / "rgba.exr");
  const std::string software = exr.get_string_attribute("Software");
  EXPECT_TRUE(software.starts_with("darc")) << software;

  // Depth: camera-space z. The sphere (radius 0.5, 5 units away) is nearest at 4.5 in the
  // middle of the frame; the corner sees nothing.
  for (const char* file : {"z.exr", "z.tif"}) {
    SCOPED_TRACE(file);
    Pixels z;
    ASSERT_TRUE(read_image(dir / file, z));
    EXPECT_NEAR(z.at(16, 12, 0), 4.5f, 0.02f);
    EXPECT_GE(z.at(0, 0, 0), kMissDepth);
  }
}

TEST(CliOutputFormats, DepthInAnEightBitFormatIsAnIoError) {
  ScratchDir dir("z-png");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "z.png", "z"));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "z.png"));
  EXPECT_FALSE(has_temp_files(dir.path()));
}

// Degenerate input every hider must survive: zero and negative widths, coincident control
// points, a zero-length segment, a curve along the view direction, a huge curve, widths from
// 1e-30 to 1e30, zero-radius and huge spheres, and collapsed polygons.
std::string degenerate_scene_rib() {
  return "Display \"degenerate.exr\" \"file\" \"rgba\"\n"
         "Format 24 16 1\n"
         "PixelSamples 2 2\n"
         "Projection \"perspective\" \"fov\" [40]\n"
         "Translate 0 0 5\n"
         "WorldBegin\n"
         "  LightSource \"distantlight\" 1 \"intensity\" [1]\n"
         "  LightSource \"pointlight\" 2 \"from\" [0 0 0] \"intensity\" [1]\n"
         "  Surface \"plastic\"\n"
         "  Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-1 -1 0  -0.3 0.5 0  0.3 -0.5 0  1 1 0] \"constantwidth\" [0]\n"
         "  Curves \"cubic\" [4] \"nonperiodic\" \"P\" [0 0 0  0 0 0  0 0 0  0 0 0] \"constantwidth\" [0.2]\n"
         "  Curves \"linear\" [2] \"nonperiodic\" \"P\" [0.2 0.1 0  0.2 0.1 0] \"constantwidth\" [0.2]\n"
         "  Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 -4.9  0 0 20] \"constantwidth\" [0.2]\n"
         "  Curves \"linear\" [2] \"nonperiodic\" \"P\" [-1e30 0 0  1e30 0.1 0] \"constantwidth\" [0.05]\n"
         "  Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-1e20 -1e20 1e20  1e20 1e20 1e20  0 1 0  1 0 0]"
         " \"width\" [1e-30 1e30]\n"
         "  Curves \"linear\" [3] \"nonperiodic\" \"P\" [0.5 0.5 0  0.5 0.5 0  0.6 0.6 0] \"width\" [0 0.1 0]\n"
         "  Curves \"linear\" [2] \"nonperiodic\" \"P\" [-1 0.3 0  1 0.3 0] \"constantwidth\" [1e30]\n"
         "  Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 -0.5 0  0 0.5 0] \"constantwidth\" [-0.1]\n"
         "  Sphere 0 -1 1 360\n"
         "  Sphere 1e30 -1e30 1e30 360\n"
         "  Polygon \"P\" [0 0 0  0 0 0  0 0 0]\n"
         "  Polygon \"P\" [0 0 0  1 0 0  2 0 0]\n"
         "WorldEnd\n";
}

class DegenerateInput : public ::testing::TestWithParam<const char*> {};

TEST_P(DegenerateInput, RendersOnlyFinitePixels) {
  const std::string hider = GetParam();
  ScratchDir dir("degenerate-" + hider);
  write_file(dir / "scene.rib", degenerate_scene_rib());
  RunResult r = run_darc(dir.path(), "--hider " + hider + " scene.rib");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("non-finite"), std::string::npos) << "the renderer produced NaN or infinity:\n" << r.err;
  Pixels p;
  ASSERT_TRUE(read_image(dir / "degenerate.exr", p));
  for (float value : p.v) ASSERT_TRUE(std::isfinite(value));
}

INSTANTIATE_TEST_SUITE_P(CliOutputFormats, DegenerateInput, ::testing::Values("distance", "stochastic"));

// Extreme scale: the camera 1e30 away from a 1e29 sphere and curve, lit by a 1e38 light.
TEST(CliOutputFormats, HugeCoordinatesRenderFinitePixels) {
  ScratchDir dir("huge");
  write_file(dir / "scene.rib",
             "Display \"huge.exr\" \"file\" \"rgba\"\n"
             "Format 8 6 1\n"
             "Projection \"perspective\" \"fov\" [40]\n"
             "Translate 0 0 1e30\n"
             "WorldBegin\n"
             "  LightSource \"pointlight\" 1 \"from\" [0 0 -1e30] \"intensity\" [1e38]\n"
             "  Surface \"matte\"\n"
             "  Sphere 1e29 -1e29 1e29 360\n"
             "  Curves \"linear\" [2] \"nonperiodic\" \"P\" [-1e30 0 0  1e30 0 0] \"constantwidth\" [1e29]\n"
             "WorldEnd\n");
  for (const char* hider : {"distance", "stochastic"}) {
    SCOPED_TRACE(hider);
    RunResult r = run_darc(dir.path(), std::string("--hider ") + hider + " scene.rib");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("non-finite"), std::string::npos) << r.err;
    Pixels p;
    ASSERT_TRUE(read_image(dir / "huge.exr", p));
    for (float value : p.v) ASSERT_TRUE(std::isfinite(value));
  }
}

}  // namespace
}  // namespace darc::test
