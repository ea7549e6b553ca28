// Reuse of what SceneBuilder built from archives replayed from the cache: the curves of a
// replayed Curves call are copied while its transform, basis and colours are unchanged (bitwise
// the segments a fresh build gives), and a frame whose every geometry request was replayed with
// the same transforms gets the geometry key that lets its acceleration structure be reused.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/scene/acceleration_reuse.h"
#include "core/scene/builder/scene_builder.h"
#include "parser/rib_parser.h"

namespace darc::test {
namespace {

namespace fs = std::filesystem;

std::vector<Scene> build_frames(const fs::path& main, bool cache) {
  std::vector<Scene> scenes;
  Diagnostics diag;
  SceneBuilder::Callbacks cb;
  cb.frame_ready = [&](Scene&& s) { scenes.push_back(std::move(s)); };
  SceneBuilder builder(diag, cb);
  RibParser parser(builder, diag);
  ArchiveCache archives;
  if (cache) parser.use_archive_cache(&archives);
  parser.parse_file(main.string());
  builder.finish(SourceLoc{});
  EXPECT_EQ(diag.error_count(), 0);
  return scenes;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_curves(const CurveSet& a, const CurveSet& b) {
  return same_bytes(a.cp, b.cp) && same_bytes(a.width, b.width) && same_bytes(a.shading_index, b.shading_index) &&
         a.shading == b.shading && same_bytes(a.normal, b.normal) && a.flags == b.flags && a.strand_id == b.strand_id &&
         a.attribute_id == b.attribute_id;
}

class ArchiveReuse : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("darc-archive-reuse-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    // Two curve requests (one oriented, with colours), a sphere, under the archive's own transform.
    std::ofstream(dir_ / "hair.rib")
        << "AttributeBegin\nColor [0.4 0.3 0.2]\nBasis \"b-spline\" 1 \"b-spline\" 1\n"
           "Curves \"cubic\" [5 6] \"nonperiodic\" \"P\" [0 0 0 0 1 0 1 1 0 1 2 0 2 2 0  0 0 1 0 1 1 1 1 1 1 2 1 2 2 1 3 3 1]"
           " \"width\" [0.1 0.09 0.08 0.07 0.06 0.05 0.04]\n"
           "Translate 0 0 2\n"
           "Curves \"linear\" [3] \"nonperiodic\" \"P\" [0 0 0 1 0 0 1 1 0] \"N\" [0 0 1 0 0 1 0 0 1]"
           " \"Cs\" [1 0 0 0 1 0 0 0 1] \"constantwidth\" [0.05]\n"
           "Sphere 0.5 -0.5 0.5 360\nAttributeEnd\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path main_rib(const std::string& frames) {
    std::ofstream(dir_ / "main.rib") << frames;
    return dir_ / "main.rib";
  }
  static std::string frame(int n, double angle, const std::string& world_extra = "") {
    return "FrameBegin " + std::to_string(n) + "\nFormat 32 24 1\nTranslate 0 0 8\nRotate " + std::to_string(angle) +
           " 0 1 0\nWorldBegin\n" + world_extra + "ReadArchive \"hair.rib\"\nReadArchive \"hair.rib\"\nWorldEnd\nFrameEnd\n";
  }
  fs::path dir_;
};

TEST_F(ArchiveReuse, CameraMoveReusesCurvesAndKeepsOneGeometryKey) {
  const fs::path main = main_rib(frame(1, 0) + frame(2, 10) + frame(3, 20));
  std::vector<Scene> cached = build_frames(main, true), fresh = build_frames(main, false);
  ASSERT_EQ(cached.size(), 3u);
  ASSERT_EQ(fresh.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(same_curves(cached[i].curves, fresh[i].curves)) << "frame " << i + 1;
    EXPECT_EQ(cached[i].surfaces.spheres.size(), 2u);
    EXPECT_TRUE(fresh[i].geometry_key.empty()) << "without the cache nothing says the geometry repeats";
  }
  EXPECT_GT(cached[0].curves.size(), 0u);
  EXPECT_FALSE(cached[0].geometry_key.empty());
  EXPECT_EQ(cached[0].geometry_key, cached[1].geometry_key);
  EXPECT_EQ(cached[1].geometry_key, cached[2].geometry_key);

  // The acceleration structure of frames 2 and 3 is frame 1's, and it is what a build gives.
  AccelerationReuse reuse;
  EXPECT_FALSE(reuse.build(cached[0]));
  EXPECT_TRUE(reuse.build(cached[1]));
  fresh[1].build_acceleration();
  EXPECT_EQ(cached[1].accel.memory_bytes(), fresh[1].accel.memory_bytes());
  EXPECT_EQ(cached[1].bounds.lo, fresh[1].bounds.lo);
  EXPECT_EQ(cached[1].bounds.hi, fresh[1].bounds.hi);
}

TEST_F(ArchiveReuse, MovedArchiveOrOtherGeometryChangesTheKey) {
  const fs::path main = main_rib(frame(1, 0) + frame(2, 0, "Translate 1 0 0\n") +
                                 frame(3, 0, "Polygon \"P\" [0 0 0 1 0 0 1 1 0]\n"));
  std::vector<Scene> cached = build_frames(main, true), fresh = build_frames(main, false);
  ASSERT_EQ(cached.size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_TRUE(same_curves(cached[i].curves, fresh[i].curves)) << "frame " << i + 1;
  EXPECT_NE(cached[0].geometry_key, cached[1].geometry_key) << "the archive moved in the world";
  EXPECT_TRUE(cached[2].geometry_key.empty()) << "a polygon of the main file is not a replayed request";
  AccelerationReuse reuse;
  EXPECT_FALSE(reuse.build(cached[0]));
  EXPECT_FALSE(reuse.build(cached[1]));
  EXPECT_FALSE(reuse.build(cached[2]));
}

}  // namespace
}  // namespace darc::test
