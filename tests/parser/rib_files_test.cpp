// Reading files: ReadArchive (relative, search path, missing, cycles), gzip, missing files.
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>

#include "recording_target.h"

namespace darc::test {
namespace {

namespace fs = std::filesystem;

// A fresh temporary directory, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / (std::string("darc_parser_") + info->name() + "_" +
                                         std::to_string(std::hash<std::string>{}(info->test_suite_name())));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = path_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

struct FileParse {
  RecordingTarget target;
  Diagnostics diag{[](const Diagnostic&) {}};
  bool ok = false;
};

std::unique_ptr<FileParse> parse_file(const std::string& path) {
  auto r = std::make_unique<FileParse>();
  RibParser parser(r->target, r->diag);
  r->ok = parser.parse_file(path);
  return r;
}

TEST(RibFiles, ReadArchiveRelativeToTheIncludingFile) {
  TempDir dir;
  dir.write("sub/part.rib", "Color 1 0 0\n\nSphere 1 -1 1 360 \"foo\" 1\n");
  const std::string main = dir.write("sub/main.rib", "WorldBegin\nReadArchive \"part.rib\"\nWorldEnd\n");
  auto r = parse_file(main);
  EXPECT_TRUE(r->ok);
  ASSERT_EQ(r->target.calls.size(), 4u);
  EXPECT_EQ(r->target.calls[1].request, "Color");
  // Positions inside the archive name the archive.
  EXPECT_EQ(r->target.calls[2].loc.line, 3);
  EXPECT_EQ(fs::path(r->target.calls[2].loc.file_name()).filename(), "part.rib");
  ASSERT_EQ(r->diag.all().size(), 1u);  // the undeclared "foo"
  EXPECT_EQ(fs::path(r->diag.all()[0].loc.file_name()).filename(), "part.rib");
  EXPECT_EQ(r->diag.all()[0].loc.line, 3);
}

TEST(RibFiles, ReadArchiveUsesTheSearchPathWithAmpersand) {
  TempDir dir;
  dir.write("lib1/a.rib", "Sides 1\n");
  dir.write("lib2/b.rib", "Sides 2\n");
  const std::string lib1 = (dir.path() / "lib1").string();
  const std::string lib2 = (dir.path() / "lib2").string();
  const std::string main = dir.write("main.rib", "Option \"searchpath\" \"archive\" [\"" + lib1 +
                                                     "\"]\nOption \"searchpath\" \"archive\" [\"" + lib2 +
                                                     ":&\"]\nReadArchive \"a.rib\"\nReadArchive \"b.rib\"\n");
  auto r = parse_file(main);
  EXPECT_TRUE(r->ok) << (r->diag.all().empty() ? "" : r->diag.all()[0].str());
  const auto sides = r->target.named("Sides");
  ASSERT_EQ(sides.size(), 2u);
  EXPECT_EQ(sides[0].numbers[0], 1);
  EXPECT_EQ(sides[1].numbers[0], 2);
  EXPECT_EQ(r->target.named("Option").size(), 2u);  // the option still reaches the target
}

TEST(RibFiles, MissingArchiveIsAnErrorAtTheRequest) {
  TempDir dir;
  const std::string main = dir.write("main.rib", "WorldBegin\n  ReadArchive \"x.rib\"\nWorldEnd\n");
  auto r = parse_file(main);
  EXPECT_FALSE(r->ok);
  ASSERT_EQ(r->diag.error_count(), 1);
  EXPECT_EQ(r->diag.all()[0].message, "cannot open archive \"x.rib\": no such file");
  EXPECT_EQ(r->diag.all()[0].loc.line, 2);
  EXPECT_EQ(r->diag.all()[0].loc.column, 3);
  EXPECT_EQ(r->target.named("WorldEnd").size(), 1u);
}

TEST(RibFiles, ArchiveFilesCanBeDisallowed) {
  TempDir dir;
  dir.write("part.rib", "Sides 1\n");
  const std::string absolute = dir.write("abs.rib", "Sides 2\n");
  const std::string main =
      dir.write("main.rib", "ReadArchive \"part.rib\"\nReadArchive \"" + absolute + "\"\nSides 1\n");
  FileParse r;
  RibParser parser(r.target, r.diag);
  parser.allow_archive_files(false);
  EXPECT_FALSE(parser.parse_file(main));
  ASSERT_EQ(r.diag.error_count(), 2);
  EXPECT_EQ(r.diag.all()[0].message, "cannot open archive \"part.rib\": file access is disabled");
  EXPECT_EQ(r.diag.all()[1].loc.line, 2);
  // Neither archive was read; the request after them was.
  ASSERT_EQ(r.target.named("Sides").size(), 1u);
  EXPECT_EQ(r.target.named("Sides")[0].loc.line, 3);
}

TEST(RibFiles, ArchiveCycleIsAnError) {
  TempDir dir;
  dir.write("a.rib", "Sides 1\nReadArchive \"b.rib\"\n");
  dir.write("b.rib", "Sides 2\nReadArchive \"a.rib\"\n");
  auto r = parse_file((dir.path() / "a.rib").string());
  EXPECT_FALSE(r->ok);
  ASSERT_EQ(r->diag.error_count(), 1);
  EXPECT_NE(r->diag.all()[0].message.find("includes itself"), std::string::npos);
  EXPECT_EQ(fs::path(r->diag.all()[0].loc.file_name()).filename(), "b.rib");
  EXPECT_EQ(r->target.named("Sides").size(), 2u);
}

TEST(RibFiles, AnInlineArchiveTakesPrecedenceOverAFileOfTheSameName) {
  TempDir dir;
  dir.write("part.rib", "Sides 2\n");
  const std::string main =
      dir.write("main.rib", "ArchiveBegin \"part.rib\" Sides 1 ArchiveEnd\nReadArchive \"part.rib\"\n");
  auto r = parse_file(main);
  EXPECT_TRUE(r->ok);
  const auto sides = r->target.named("Sides");
  ASSERT_EQ(sides.size(), 1u);
  EXPECT_EQ(sides[0].numbers[0], 1) << "as in PRMan, the inline archive is read, not the file";
}

TEST(RibFiles, ABrokenZipArchiveIsAClearError) {
  TempDir dir;
  dir.write("assets.zip", "PK");
  const std::string main = dir.write("main.rib", "ReadArchive \"assets.zip!hair.rib\"\nSides 1\n");
  auto r = parse_file(main);
  ASSERT_EQ(r->diag.error_count(), 1);
  EXPECT_EQ(r->diag.all()[0].message.rfind("cannot open archive \"assets.zip!hair.rib\": not a readable zip file", 0),
            0u)
      << r->diag.all()[0].message;
  EXPECT_EQ(r->diag.all()[0].loc.line, 1);
  EXPECT_EQ(r->target.named("Sides").size(), 1u);
}

TEST(RibFiles, GzipFilesAreDecompressed) {
  TempDir dir;
  const std::string path = (dir.path() / "scene.rib.gz").string();
  const std::string text = "WorldBegin\nCurves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 0 1 1 1]\nWorldEnd\n";
  gzFile file = gzopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  ASSERT_EQ(gzwrite(file, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  gzclose(file);
  auto r = parse_file(path);
  EXPECT_TRUE(r->ok);
  ASSERT_EQ(r->target.calls.size(), 3u);
  EXPECT_EQ(r->target.calls[1].loc.line, 2);
}

TEST(RibFiles, MissingFileIsAnError) {
  auto r = parse_file("/nonexistent/dir/scene.rib");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->diag.error_count(), 1);
}

TEST(RibFiles, SharedReadArchiveExample) {
  const std::string path = DARC_SHARED_RIBS_DIR "/aqsis/RIBProcessing_readarchive.rib";
  if (!fs::exists(path)) GTEST_SKIP() << "shared RIBs not found at " << path;
  auto r = parse_file(path);
  EXPECT_TRUE(r->ok);
  const auto polygons = r->target.named("Polygon");
  ASSERT_EQ(polygons.size(), 3u);
  // The middle polygon comes from simple_archive.rib (a red triangle).
  EXPECT_EQ(polygons[1].params.find("P")->element_count(), 3u);
  EXPECT_EQ(fs::path(polygons[1].loc.file_name()).filename(), "simple_archive.rib");
}

}  // namespace
}  // namespace darc::test
