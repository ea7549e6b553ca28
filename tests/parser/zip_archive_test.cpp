// Members of zip files as archives ("cache.zip!member.rib", RenderMan for Maya 21+'s geometry
// caches read through Procedural2 "DelayedReadArchive2"): read with libzip, found as file archives
// are, cached, and clear errors for a broken zip or a missing member.
#include <gtest/gtest.h>
#include <zip.h>

#include <map>

#include "parser/archive_cache.h"
#include "parser/zip_member.h"
#include "procedural_test_util.h"

namespace darc::test {
namespace {

// Writes a zip file at `path` holding `members` (name -> text), deflated as RfM writes them.
void write_zip(const std::string& path, const std::map<std::string, std::string>& members) {
  fs::create_directories(fs::path(path).parent_path());
  int code = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
  ASSERT_NE(z, nullptr) << code;
  for (const auto& [name, text] : members) {
    zip_source_t* src = zip_source_buffer(z, text.data(), text.size(), 0);
    ASSERT_NE(src, nullptr);
    ASSERT_GE(zip_file_add(z, name.c_str(), src, ZIP_FL_OVERWRITE), 0) << zip_strerror(z);
  }
  ASSERT_EQ(zip_close(z), 0);  // the buffers are read here, while `members` still holds them
}

std::vector<std::string> requests(const RecordingTarget& t) {
  std::vector<std::string> out;
  for (const RecordedCall& c : t.calls) out.push_back(c.request);
  return out;
}

TEST(ZipMemberName, SplitsAtTheFirstZipBang) {
  const auto a = split_zip_member("renderman/proj/staticGeoCache.job.ZIP!renderman/proj/pCubeShape1.job.rib");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->zip, "renderman/proj/staticGeoCache.job.ZIP");
  EXPECT_EQ(a->member, "renderman/proj/pCubeShape1.job.rib");
  EXPECT_FALSE(split_zip_member("hair.rib"));
  EXPECT_FALSE(split_zip_member("zip!hair.rib"));
}

TEST(ZipArchive, AMemberIsReadAsTheArchive) {
  ScratchFolder dir;
  write_zip((dir / "assets.zip").string(), {{"geo/hair.rib", "Sides 2\nSphere 1 -1 1 360\n"}, {"other.rib", "Sides 1\n"}});
  auto r = parse_procedural("ReadArchive \"assets.zip!geo/hair.rib\"\nColor 1 0 0\n", (dir / "main.rib").string());
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(requests(r->target), (std::vector<std::string>{"Sides", "Sphere", "Color"}));
  // Positions inside the member name it.
  EXPECT_NE(r->target.calls[1].loc.file_name().find("assets.zip!geo/hair.rib"), std::string::npos);
  EXPECT_EQ(r->target.calls[1].loc.line, 2);
}

TEST(ZipArchive, DelayedReadArchive2ReadsAMemberAsRenderManForMayaWritesIt) {
  // The shape of an RfM 21+ export: the shape's RIB inside a zip cache, read when its bound is hit.
  ScratchFolder dir;
  write_zip((dir / "renderman/scene/data/staticGeoCache.job.zip").string(),
            {{"renderman/scene/data/pCubeShape1.job.rib",
              "PointsPolygons [4] [0 1 2 3] \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]\n"}});
  auto r = parse_procedural(
      "WorldBegin\nProcedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" "
      "[\"renderman/scene/data/staticGeoCache.job.zip!renderman/scene/data/pCubeShape1.job.rib\"] "
      "\"float[6] bound\" [-1 1 -1 1 0 0]\nWorldEnd\n",
      (dir / "scene.rib").string());
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(requests(r->target),
            (std::vector<std::string>{"WorldBegin", "AttributeBegin", "PointsPolygons", "AttributeEnd", "WorldEnd"}));
}

TEST(ZipArchive, AMissingMemberOrABrokenZipIsAnErrorAtTheRequest) {
  ScratchFolder dir;
  write_zip((dir / "assets.zip").string(), {{"hair.rib", "Sides 2\n"}});
  dir.write("broken.zip", "PK");
  auto r = parse_procedural(
      "ReadArchive \"assets.zip!nope.rib\"\nReadArchive \"broken.zip!hair.rib\"\nReadArchive \"absent.zip!hair.rib\"\n"
      "Sides 1\n",
      (dir / "main.rib").string());
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].message, "cannot open archive \"assets.zip!nope.rib\": the zip file has no such member");
  EXPECT_EQ(errors[0].loc.line, 1);
  EXPECT_TRUE(contains(errors[1].message, "cannot open archive \"broken.zip!hair.rib\": not a readable zip file"))
      << errors[1].message;
  EXPECT_EQ(errors[1].loc.line, 2);
  EXPECT_EQ(errors[2].message, "cannot open archive \"absent.zip!hair.rib\": no such zip file");
  EXPECT_EQ(r->target.named("Sides").size(), 1u);  // the request after them is read
}

TEST(ZipArchive, AMemberLargerThanTheTextLimitIsRefusedBeforeItIsRead) {
  ScratchFolder dir;
  write_zip((dir / "assets.zip").string(), {{"big.rib", "Sides 2\n" + std::string(4096, '#') + "\n"}});
  auto r = parse_procedural("ReadArchive \"assets.zip!big.rib\"\n", (dir / "main.rib").string(), [](RibParser& p) { p.set_text_limit(1000, "a test"); });
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_TRUE(contains(r->errors()[0].message, "more than 1000")) << r->errors()[0].message;
  EXPECT_TRUE(r->target.named("Sides").empty());
}

TEST(ZipArchive, AnArchiveNamedInsideAMemberIsFoundBesideTheZip) {
  ScratchFolder dir;
  dir.write("cache/part.rib", "Sphere 1 -1 1 360\n");
  write_zip((dir / "cache/assets.zip").string(), {{"sub/shape.rib", "ReadArchive \"part.rib\"\n"}});
  auto r = parse_procedural("ReadArchive \"cache/assets.zip!sub/shape.rib\"\n", (dir / "main.rib").string());
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(r->target.named("Sphere").size(), 1u);
}

TEST(ZipArchive, AMemberReadTwiceIsParsedOnceWithTheArchiveCache) {
  ScratchFolder dir;
  write_zip((dir / "assets.zip").string(), {{"hair.rib", "Sides 2\n"}});
  ArchiveCache cache;
  auto r = parse_procedural("ReadArchive \"assets.zip!hair.rib\"\nReadArchive \"assets.zip!hair.rib\"\n",
                            (dir / "main.rib").string(), [&](RibParser& p) { p.use_archive_cache(&cache); });
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(r->target.named("Sides").size(), 2u);
  EXPECT_EQ(cache.replays(), 1);
}

}  // namespace
}  // namespace darc::test
