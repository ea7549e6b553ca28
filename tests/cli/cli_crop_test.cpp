// darc --crop xmin xmax ymin ymax (prman -crop): every frame is cropped as CropWindow would crop
// it, overriding the RIB's CropWindow; the file keeps the full display window with the crop as its
// data window, bitwise the whole image's pixels there. Bad ranges are usage errors (exit 2); a
// crop that keeps no pixel of a frame is that frame's scene error, as for CropWindow.
#include <cstring>

#include "support/darc_command.h"
#include "support/image_files.h"
#include "support/test_frames.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitSceneError = 3;

// Two 32x24 frames, the RIB cropping both to their left half: --crop replaces that.
std::string two_cropped_frames() {
  std::string rib = tiny_frame_rib(1, "f#.exr") + tiny_frame_rib(2, "f#.exr");
  for (size_t at = rib.find("PixelSamples"); at != std::string::npos; at = rib.find("PixelSamples", at + 40))
    rib.insert(at, "CropWindow 0 0.5 0 1\n");
  return rib;
}

TEST(CliCrop, OverridesTheRibsCropWindowInEveryFrameWithTheWholeImagesPixels) {
  ScratchDir dir("crop");
  write_file(dir / "scene.rib", two_cropped_frames());
  write_file(dir / "whole.rib", tiny_frame_rib(1, "whole.exr"));
  ASSERT_EQ(run_darc(dir.path(), "whole.rib").exit_code, kExitOk);
  RunResult r = run_darc(dir.path(), "--crop 0.25 1 0.5 0.75 scene.rib");
  ASSERT_EQ(r.exit_code, kExitOk) << r.err;
  Pixels whole;
  ASSERT_TRUE(read_image(dir / "whole.exr", whole));
  for (const char* frame : {"f1.exr", "f2.exr"}) {
    SCOPED_TRACE(frame);
    const std::optional<OIIO::ImageSpec> header = read_image_header(dir / frame);
    ASSERT_TRUE(header);
    // Columns ceil(32 * 0.25) = 8 to 31, rows ceil(24 * 0.5) = 12 to ceil(24 * 0.75 - 1) = 17.
    EXPECT_EQ((std::array{header->x, header->y, header->width, header->height}), (std::array{8, 12, 24, 6}));
    EXPECT_EQ((std::array{header->full_x, header->full_y, header->full_width, header->full_height}),
              (std::array{0, 0, 32, 24}));
    Pixels crop;
    ASSERT_TRUE(read_image(dir / frame, crop));
    for (int y = 0; y < crop.height; ++y)
      for (int x = 0; x < crop.width; ++x)
        for (int c = 0; c < crop.channels; ++c) {
          const float a = crop.at(x, y, c), b = whole.at(x + 8, y + 12, c);
          ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "pixel " << x + 8 << ", " << y + 12 << " channel " << c;
        }
  }
}

TEST(CliCrop, BadRangesAreUsageErrorsAndWriteNothing) {
  ScratchDir dir("crop-usage");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "scene.exr"));
  for (const char* args : {"--crop 0.5 0.25 0 1 scene.rib", "--crop 0 1 0 1.5 scene.rib", "--crop 0 1 -0.5 1 scene.rib",
                           "--crop 0 1 0.5 0.5 scene.rib", "--crop 0 1 0 scene.rib", "--crop 0 1 0 x scene.rib",
                           "--crop 0 1 0 1 --crop 0 1 0 1 scene.rib"}) {
    SCOPED_TRACE(args);
    RunResult r = run_darc(dir.path(), args);
    EXPECT_EQ(r.exit_code, kExitUsage) << r.err;
    EXPECT_NE(r.err.find("--crop"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "scene.exr"));
  }
  RunResult r = run_darc(dir.path(), "--crop 0.5 0.25 0 1 scene.rib");
  EXPECT_NE(r.err.find("expected xmin xmax ymin ymax with 0 <= xmin < xmax <= 1 and 0 <= ymin < ymax <= 1, found "
                       "\"0.5 0.25 0 1\""),
            std::string::npos)
      << r.err;
}

TEST(CliCrop, ACropWithoutAPixelIsTheFramesSceneErrorNamingTheOption) {
  ScratchDir dir("crop-no-pixel");
  write_file(dir / "scene.rib", tiny_frame_rib(1, "scene.exr", "rgba", 10, 10));
  RunResult r = run_darc(dir.path(), "--crop 0 1 0.01 0.02 scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("error: --crop: [0 1 0.01 0.02] keeps no pixel of the 10x10 image: the whole image is rendered"),
            std::string::npos)
      << r.err;
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "scene.exr");
  ASSERT_TRUE(header);
  EXPECT_EQ(header->get_int_attribute("darc:errors"), 1);
  EXPECT_EQ(header->height, 10);
}

}  // namespace
}  // namespace darc::test
