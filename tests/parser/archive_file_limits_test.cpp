// What a RIB may make the parser read: an archive must be a regular file that gives no more than
// its size (a device, a named pipe, a directory or a file of /proc is refused with an error at
// the request, before anything hangs or fills memory), and no text, a .gz once inflated
// included, may be larger than the parser's text limit.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zlib.h>

#include "procedural_test_util.h"

namespace darc::test {
namespace {

// Writes `bytes` spaces as a gzip file: a few kB on disk for megabytes of text.
void write_gzip_of_spaces(const fs::path& path, size_t bytes) {
  gzFile file = gzopen(path.c_str(), "wb9");
  ASSERT_NE(file, nullptr);
  const std::string block(1 << 16, ' ');
  for (size_t written = 0; written < bytes; written += block.size()) {
    const unsigned n = static_cast<unsigned>(std::min(block.size(), bytes - written));
    ASSERT_EQ(gzwrite(file, block.data(), n), static_cast<int>(n));
  }
  gzclose(file);
}

std::function<void(RibParser&)> text_limit(std::uint64_t bytes) {
  return [bytes](RibParser& p) { p.set_text_limit(bytes, "the test's limit"); };
}

TEST(ArchiveFileLimits, AnArchiveThatIsNotARegularFileIsAnErrorAtItsRequest) {
  ScratchFolder dir;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  fs::create_directories(dir / "folder");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/dev/zero", "a character device, not a regular file: archives must be regular files"},
      {(dir / "pipe").string(), "a named pipe, not a regular file: archives must be regular files"},
      {(dir / "folder").string(), "is a directory"},
      {"/proc/self/environ", "gives more than the 0 bytes its size says (a file of /proc or /sys"},
      {"/proc/self/pagemap", "gives more than the 0 bytes its size says"},
  };
  for (const auto& [name, why] : cases) {
    for (const std::string& request :
         {"ReadArchive \"" + name + "\"", "Procedural \"DelayedReadArchive\" [\"" + name + "\"] [0 1 0 1 0 1]",
          "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" [\"" + name +
              "\"] \"float[6] bound\" [0 1 0 1 0 1]"}) {
      SCOPED_TRACE(request);
      auto r = parse_procedural("Sides 1\n  " + request + "\nSides 2\n", "scene.rib");
      const auto errors = r->errors();
      ASSERT_EQ(errors.size(), 1u);
      EXPECT_EQ(errors[0].loc.str(), "scene.rib:2:3");
      EXPECT_EQ(errors[0].message.rfind("cannot open archive \"" + name + "\": ", 0), 0u) << errors[0].message;
      EXPECT_TRUE(contains(errors[0].message, why)) << errors[0].message;
      EXPECT_EQ(r->target.named("Sides").size(), 2u) << "parsing goes on after the request";
    }
  }
}

TEST(ArchiveFileLimits, AnArchiveLargerThanTheTextLimitIsAnError) {
  ScratchFolder dir;
  dir.write("big.rib", std::string(3000, ' ') + "Sides 1\n");
  dir.write("small.rib", "Sides 2\n");
  auto r = parse_procedural("ReadArchive \"big.rib\"\nReadArchive \"small.rib\"\n", (dir / "scene.rib").string(),
                            text_limit(2000));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].loc.line, 1);
  EXPECT_EQ(errors[0].message,
            "cannot open archive \"big.rib\": holds more than 2000 bytes, the most a RIB text may be (the test's "
            "limit)");
  const auto sides = r->target.named("Sides");
  ASSERT_EQ(sides.size(), 1u);
  EXPECT_EQ(sides[0].numbers[0], 2);
}

// A gzip bomb: 8 MiB of spaces in a file of a few kB, read under a 1 MiB limit. The limit holds
// what is inflated (not the file's size), so the read stops at 1 MiB.
TEST(ArchiveFileLimits, AGzipArchiveStopsInflatingAtTheTextLimit) {
  ScratchFolder dir;
  write_gzip_of_spaces(dir / "bomb.rib.gz", size_t(8) << 20);
  ASSERT_LT(fs::file_size(dir / "bomb.rib.gz"), 64u << 10) << "the test file itself stays small";
  auto r = parse_procedural("ReadArchive \"bomb.rib.gz\"\n", (dir / "scene.rib").string(), text_limit(1 << 20));
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message,
            "cannot open archive \"bomb.rib.gz\": decompresses to more than 1 MiB, the most a RIB text may be (the "
            "test's limit)");
  // Under a larger limit the same file reads (as nothing but white space).
  auto fine = parse_procedural("ReadArchive \"bomb.rib.gz\"\n", (dir / "scene.rib").string(), text_limit(16 << 20));
  EXPECT_TRUE(fine->ok) << fine->first_error();
}

// Distinct files that read each other 70 deep (no cycle): the read that would make the 65th level
// is an error, once, and the levels above it are read.
TEST(ArchiveFileLimits, ArchivesNestDeeperThan64LevelsNever) {
  ScratchFolder dir;
  const auto name = [](int i) {
    std::string n = "a";
    n += std::to_string(i);
    n += ".rib";
    return n;
  };
  for (int i = 1; i < 70; ++i) dir.write(name(i), "Sides 1\nReadArchive \"" + name(i + 1) + "\"\n");
  dir.write("a70.rib", "Sides 1\n");
  auto r = parse_procedural("ReadArchive \"a1.rib\"\n", (dir / "scene.rib").string());
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "archive \"a64.rib\" is nested deeper than 64 levels");
  EXPECT_EQ(errors[0].loc.file_name(), (dir / "a63.rib").string());
  EXPECT_EQ(r->target.named("Sides").size(), 63u);
}

TEST(ArchiveFileLimits, AnInputFileLargerThanTheTextLimitIsAnError) {
  ScratchFolder dir;
  const std::string path = dir.write("scene.rib", "Sides 1\n" + std::string(5000, '\n'));
  BoundRecordingTarget target;
  Diagnostics diag{[](const Diagnostic&) {}};
  RibParser parser(target, diag);
  parser.set_text_limit(4096, "the test's limit");
  EXPECT_FALSE(parser.parse_file(path));
  ASSERT_EQ(diag.all().size(), 1u);
  EXPECT_EQ(diag.all()[0].message, "cannot read \"" + path +
                                       "\": holds more than 4096 bytes, the most a RIB text may be (the test's limit)");
  EXPECT_TRUE(target.calls.empty()) << "nothing of it is parsed";
}

}  // namespace
}  // namespace darc::test
