// The archive cache: an archive read many times is parsed once and replayed, the target sees
// exactly the calls a fresh parse gives, errors are reported at every read (each frame records
// its own), and a change of the file, of an archive it reads, or of the declarations it was
// parsed under makes it parsed again.
#include "parser/archive_cache.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "parser/recording_target.h"

namespace darc::test {
namespace {

namespace fs = std::filesystem;

class ArchiveCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("darc-archive-cache-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  // Parses `main` (named main.rib in the test folder) into a recording target, with `cache` or none.
  struct Parsed {
    RecordingTarget target;
    std::vector<Diagnostic> diagnostics;
    int errors = 0;
  };
  std::unique_ptr<Parsed> parse(const std::string& main, ArchiveCache* cache) {
    auto out = std::make_unique<Parsed>();
    Diagnostics diag([&](const Diagnostic& d) { out->diagnostics.push_back(d); });
    RibParser parser(out->target, diag);
    parser.use_archive_cache(cache);
    write("main.rib", main);
    parser.parse_file((dir_ / "main.rib").string());
    out->errors = int(diag.error_count());
    return out;
  }
  static void expect_same_calls(const Parsed& a, const Parsed& b) {
    ASSERT_EQ(a.target.calls.size(), b.target.calls.size());
    for (size_t i = 0; i < a.target.calls.size(); ++i) {
      EXPECT_TRUE(a.target.calls[i].same_as(b.target.calls[i])) << "call " << i << ": " << a.target.calls[i].request;
      EXPECT_EQ(a.target.calls[i].loc.str(), b.target.calls[i].loc.str()) << "call " << i;
    }
  }
  fs::path dir_;
};

const char* kHair =
    "AttributeBegin\n"
    "Color [0.4 0.3 0.2]\n"
    "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [0 0 0 0 1 0 1 1 0 1 2 0] \"constantwidth\" [0.1]\n"
    "AttributeEnd\n";

TEST_F(ArchiveCacheTest, ArchiveReadThreeTimesIsParsedOnceAndGivesTheCallsOfAFreshParse) {
  write("hair.rib", kHair);
  const std::string main = "ReadArchive \"hair.rib\"\nTranslate 1 0 0\nReadArchive \"hair.rib\"\nReadArchive \"hair.rib\"\n";
  ArchiveCache cache;
  auto cached = parse(main, &cache);
  auto fresh = parse(main, nullptr);
  EXPECT_EQ(cache.parses(), 1);
  EXPECT_EQ(cache.replays(), 2);
  EXPECT_EQ(cached->target.named("Curves").size(), 3u);
  expect_same_calls(*cached, *fresh);
}

TEST_F(ArchiveCacheTest, ErrorsInTheArchiveAreReportedAtEveryReadWarningsOnce) {
  write("bad.rib", "Color [1 0 0]\nSphere \"one\" -1 1 360\nFrobnicate 3\n");
  ArchiveCache cache;
  auto cached = parse("ReadArchive \"bad.rib\"\nReadArchive \"bad.rib\"\n", &cache);
  auto fresh = parse("ReadArchive \"bad.rib\"\nReadArchive \"bad.rib\"\n", nullptr);
  EXPECT_EQ(cache.replays(), 1);
  EXPECT_EQ(cached->errors, 2) << "each read reports the malformed Sphere (a frame counts its own errors)";
  EXPECT_EQ(cached->errors, fresh->errors);
  ASSERT_EQ(cached->diagnostics.size(), fresh->diagnostics.size());
  for (size_t i = 0; i < cached->diagnostics.size(); ++i)
    EXPECT_EQ(cached->diagnostics[i].str(), fresh->diagnostics[i].str());
  expect_same_calls(*cached, *fresh);
}

TEST_F(ArchiveCacheTest, DeclarationsInsideTheArchiveHoldAfterItsReplay) {
  write("decl.rib", "Declare \"thickness\" \"uniform float\"\n");
  // The second read is parsed again (the declarations in effect are no longer those the first
  // parse saw: its own); the third is a replay, after which "thickness" must still be known.
  const std::string main =
      "ReadArchive \"decl.rib\"\nReadArchive \"decl.rib\"\nReadArchive \"decl.rib\"\nSurface \"s\" \"thickness\" [2]\n";
  ArchiveCache cache;
  auto cached = parse(main, &cache);
  EXPECT_EQ(cache.parses(), 2);
  EXPECT_EQ(cache.replays(), 1);
  EXPECT_EQ(cached->errors, 0);
  ASSERT_EQ(cached->target.named("Surface").size(), 1u);
  expect_same_calls(*cached, *parse(main, nullptr));
}

TEST_F(ArchiveCacheTest, ArchiveParsedUnderOtherDeclarationsIsParsedAgain) {
  // "a" is an inline-declared name here: how the archive's parameter parses depends on it.
  write("uses.rib", "Surface \"s\" \"a\" [1 2 3]\n");
  const std::string main = "Declare \"a\" \"uniform color\"\nReadArchive \"uses.rib\"\n"
                           "Declare \"a\" \"uniform float[3]\"\nReadArchive \"uses.rib\"\n";
  ArchiveCache cache;
  auto cached = parse(main, &cache);
  EXPECT_EQ(cache.parses(), 2);
  EXPECT_EQ(cache.replays(), 0);
  expect_same_calls(*cached, *parse(main, nullptr));
}

TEST_F(ArchiveCacheTest, ChangedFileOrChangedNestedArchiveIsParsedAgain) {
  write("inner.rib", "Sphere 1 -1 1 360\n");
  write("outer.rib", "ReadArchive \"inner.rib\"\n");
  ArchiveCache cache;
  auto first = parse("ReadArchive \"outer.rib\"\n", &cache);
  EXPECT_EQ(first->target.named("Sphere").size(), 1u);
  EXPECT_EQ(cache.parses(), 2);  // outer, and inner inside it
  // Same size, later modification time: the stamp still differs.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  write("inner.rib", "Sphere 2 -2 2 360\n");
  fs::last_write_time(dir_ / "inner.rib", fs::last_write_time(dir_ / "inner.rib") + std::chrono::seconds(2));
  auto second = parse("ReadArchive \"outer.rib\"\n", &cache);
  ASSERT_EQ(second->target.named("Sphere").size(), 1u);
  EXPECT_EQ(second->target.named("Sphere")[0].numbers[0], 2.0) << "the nested archive's new text is read";
  auto third = parse("ReadArchive \"outer.rib\"\n", &cache);
  EXPECT_EQ(third->target.named("Sphere")[0].numbers[0], 2.0);
  EXPECT_EQ(cache.replays(), 1) << "only the third parse replays";
}

TEST_F(ArchiveCacheTest, ArchiveWithAnErrorHandlerIsParsedEachTime) {
  write("policy.rib", "ErrorHandler \"ignore\"\nSphere \"x\"\n");
  ArchiveCache cache;
  auto cached = parse("ReadArchive \"policy.rib\"\nReadArchive \"policy.rib\"\n", &cache);
  auto fresh = parse("ReadArchive \"policy.rib\"\nReadArchive \"policy.rib\"\n", nullptr);
  EXPECT_EQ(cache.replays(), 0);
  EXPECT_EQ(cached->errors, fresh->errors);
  EXPECT_EQ(cached->diagnostics.size(), fresh->diagnostics.size()) << "the handler applies as without a cache";
}

TEST_F(ArchiveCacheTest, ConditionalArchiveIsParsedAtEachReadAndTakesEachFramesBranch) {
  write("cond.rib", "IfBegin \"$Frame == 2\"\nSphere 2 -2 2 360\nElse\nSphere 1 -1 1 360\nIfEnd\n");
  const std::string main = "FrameBegin 1\nReadArchive \"cond.rib\"\nFrameEnd\nFrameBegin 2\nReadArchive \"cond.rib\"\nFrameEnd\n";
  ArchiveCache cache;
  auto cached = parse(main, &cache);
  EXPECT_EQ(cache.replays(), 0);
  const auto spheres = cached->target.named("Sphere");
  ASSERT_EQ(spheres.size(), 2u);
  EXPECT_EQ(spheres[0].numbers[0], 1.0);
  EXPECT_EQ(spheres[1].numbers[0], 2.0);
  expect_same_calls(*cached, *parse(main, nullptr));
}

TEST_F(ArchiveCacheTest, AttributesSetByAReplayedArchiveAreSeenByLaterConditions) {
  write("attr.rib", "Attribute \"user\" \"string look\" [\"wet\"]\n");
  const std::string main = "WorldBegin\nReadArchive \"attr.rib\"\nAttribute \"user\" \"string look\" [\"dry\"]\n"
                           "ReadArchive \"attr.rib\"\nIfBegin \"$user:look == 'wet'\"\nSphere 1 -1 1 360\nIfEnd\nWorldEnd\n";
  ArchiveCache cache;
  auto cached = parse(main, &cache);
  EXPECT_EQ(cache.replays(), 1);
  EXPECT_EQ(cached->target.named("Sphere").size(), 1u) << "the replayed Attribute set look to wet again";
  expect_same_calls(*cached, *parse(main, nullptr));
}

}  // namespace
}  // namespace darc::test
