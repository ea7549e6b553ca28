// End-to-end: a camera move over a hair archive. The archive is parsed once and its curves and
// BVH are reused, the images are bitwise those without the cache, and a frame rendered alone
// (--frames) is bitwise the same frame of the whole run.
#include <nlohmann/json.hpp>
#include <random>

#include "support/cubic_strands.h"
#include "support/darc_command.h"
#include "support/image_files.h"

namespace darc::test {
namespace {

// 300 random B-spline strands of 6 control points hanging from y = -1 upwards, each drifting
// sideways at random as it rises.
std::string hair_archive() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  float x = 0, z = 0;
  const StrandPoint point = [&](int, int v) {
    if (v == 0) {
      x = u(rng);
      z = u(rng);
    }
    return Vec3f{x + 0.05f * float(v) * u(rng), -1.0f + 0.4f * float(v), z};
  };
  return "AttributeBegin\nColor [0.5 0.35 0.2]\nSurface \"hair\"\nBasis \"b-spline\" 1 \"b-spline\" 1\n" +
         cubic_strands(300, 6, point, 0.02f) + "AttributeEnd\n";
}

std::string camera_move(int frames) {
  std::string rib;
  for (int f = 1; f <= frames; ++f)
    rib += "FrameBegin " + std::to_string(f) + "\nDisplay \"move.#.exr\" \"file\" \"rgba\"\nFormat 48 36 1\n"
           "PixelSamples 1 1\nProjection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nRotate " +
           std::to_string(7 * f) + " 0 1 0\nWorldBegin\nLightSource \"distantlight\" 1 \"from\" [0 2 -2]\n"
           "ReadArchive \"hair.rib\"\nWorldEnd\nFrameEnd\n";
  return rib;
}

Pixels pixels(const fs::path& p) {
  Pixels out;
  EXPECT_TRUE(read_image(p, out)) << p;
  return out;
}

TEST(CliArchiveSequence, ArchiveParsedOnceImagesAsWithoutCacheAndFrameAloneAsInTheRun) {
  ScratchDir dir("archive-sequence");
  write_file(dir / "hair.rib", hair_archive());
  write_file(dir / "move.rib", camera_move(4));
  ASSERT_EQ(run_darc(dir.path(), "--stats stats.json move.rib").exit_code, 0);
  std::vector<Pixels> run;
  for (int f = 1; f <= 4; ++f) run.push_back(pixels(dir / ("move." + std::to_string(f) + ".exr")));

  const nlohmann::json stats = nlohmann::json::parse(read_text_file(dir / "stats.json"));
  EXPECT_EQ(stats["archive_cache"]["archives_parsed"], 1);
  EXPECT_EQ(stats["archive_cache"]["archives_replayed"], 3);
  ASSERT_EQ(stats["frames"].size(), 4u);
  EXPECT_FALSE(stats["frames"][0]["accelerator_reused"].get<bool>());
  for (int i = 1; i < 4; ++i) EXPECT_TRUE(stats["frames"][i]["accelerator_reused"].get<bool>()) << "frame " << i + 1;

  ASSERT_EQ(run_darc(dir.path(), "--no-archive-cache move.rib").exit_code, 0);
  for (int f = 1; f <= 4; ++f)
    EXPECT_TRUE(pixels(dir / ("move." + std::to_string(f) + ".exr")).identical_to(run[size_t(f - 1)]))
        << "frame " << f << " without the cache";

  for (int f : {1, 3}) {
    fs::remove(dir / ("move." + std::to_string(f) + ".exr"));
    ASSERT_EQ(run_darc(dir.path(), "--frames " + std::to_string(f) + " move.rib").exit_code, 0);
    EXPECT_TRUE(pixels(dir / ("move." + std::to_string(f) + ".exr")).identical_to(run[size_t(f - 1)]))
        << "frame " << f << " alone";
  }
  EXPECT_GT(run[0].v.size(), 0u);
  EXPECT_FALSE(run[0].identical_to(run[1])) << "the camera moves";
}

}  // namespace
}  // namespace darc::test
