// Procedural and Procedural2 requests: how they are read, DelayedReadArchive, DynamicLoad, the
// bound (asked of the target, which may decline), and the refusal when file access is off.
// RunProgram's process and its search rule: run_program_test.cpp.
#include <gtest/gtest.h>

#include "procedural_test_util.h"

namespace darc::test {
namespace {

std::vector<std::string> requests(const RecordingTarget& t) {
  std::vector<std::string> out;
  for (const RecordedCall& c : t.calls) out.push_back(c.request);
  return out;
}

using Names = std::vector<std::string>;

TEST(Procedural, DelayedReadArchiveReadsTheArchiveInsideAnAttributeBlock) {
  ScratchFolder dir;
  dir.write("part.rib", "Color 1 0 0\nSphere 1 -1 1 360\n");
  auto r = parse_procedural(
      "WorldBegin\n  Procedural \"DelayedReadArchive\" [\"part.rib\"] [-1 1 -1 1 -1 1]\nSphere 2 -2 2 360\nWorldEnd\n",
      (dir / "scene.rib").string());
  EXPECT_TRUE(r->ok) << r->first_error();
  // The archive's Color stays inside: the Sphere after the request keeps the state before it.
  EXPECT_EQ(requests(r->target),
            (Names{"WorldBegin", "AttributeBegin", "Color", "Sphere", "AttributeEnd", "Sphere", "WorldEnd"}));
  const RecordedCall& inner = r->target.calls[3];
  EXPECT_EQ(fs::path(inner.loc.file_name()).filename(), "part.rib");
  EXPECT_EQ(inner.loc.line, 2);
  // The wrapping block carries the request's position.
  EXPECT_EQ(r->target.calls[1].loc.line, 2);
  EXPECT_EQ(r->target.calls[1].loc.column, 3);
  ASSERT_EQ(r->target.bounds.size(), 1u);
  EXPECT_EQ(r->target.bounds[0], (std::array<double, 6>{-1, 1, -1, 1, -1, 1}));
}

TEST(Procedural, Procedural2DelayedReadArchive2BehavesAsDelayedReadArchive) {
  ScratchFolder dir;
  dir.write("mesh.rib", "Sphere 1 -1 1 360\n");
  auto r = parse_procedural(
      "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" [\"mesh.rib\"] "
      "\"float[6] bound\" [-1 1 -2 2 -3 3] \"int __immediatesubdivide\" [0]\n",
      (dir / "scene.rib").string());
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(requests(r->target), (Names{"AttributeBegin", "Sphere", "AttributeEnd"}));
  ASSERT_EQ(r->target.bounds.size(), 1u);
  EXPECT_EQ(r->target.bounds[0], (std::array<double, 6>{-1, 1, -2, 2, -3, 3}));
}

TEST(Procedural, Procedural2NeedsItsFilenameAndBound) {
  ScratchFolder dir;
  dir.write("mesh.rib", "Sphere 1 -1 1 360\n");
  auto r = parse_procedural(
      "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"float[6] bound\" [-1 1 -1 1 -1 1]\n"
      "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" [\"mesh.rib\"]\n"
      "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" [\"mesh.rib\"] \"float bound\" [1 2]\n",
      (dir / "scene.rib").string());
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 3u) << r->first_error();
  EXPECT_EQ(errors[0].message, "DelayedReadArchive2 needs one \"string filename\"");
  EXPECT_EQ(errors[1].message, "DelayedReadArchive2 needs \"float[6] bound\"");
  EXPECT_EQ(errors[2].message, "\"bound\" needs 6 numbers (xmin xmax ymin ymax zmin zmax), found 2");
  EXPECT_EQ(errors[2].loc.line, 3);
  EXPECT_TRUE(r->target.calls.empty());
}

TEST(Procedural, MalformedArgumentsAreErrorsAtTheirPosition) {
  auto r = parse_procedural(
      "Procedural \"DelayedReadArchive\" [\"a.rib\" \"b.rib\"] [-1 1 -1 1 -1 1]\n"
      "Procedural \"RunProgram\" [\"gen.py\"] [-1 1 -1 1 -1 1]\n"
      "Procedural \"DelayedReadArchive\" [\"a.rib\"] [-1 1 -1 1 -1]\n"
      "Procedural \"DelayedReadArchive\" [\"a.rib\"] [1 -1 -1 1 -1 1]\n"
      "Procedural \"DelayedReadArchive\" [3] [-1 1 -1 1 -1 1]\n"
      "Sides 1\n",
      "scene.rib");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 5u) << r->first_error();
  EXPECT_EQ(errors[0].message, "DelayedReadArchive takes one string, the file name (found 2)");
  EXPECT_EQ(errors[0].request, "Procedural");
  EXPECT_EQ(errors[0].loc.str(), "scene.rib:1:1");
  EXPECT_EQ(errors[1].message, "RunProgram takes two strings, the program and its data (found 1)");
  EXPECT_EQ(errors[2].loc.str(), "scene.rib:3:56");  // the ']' where the sixth number should be
  EXPECT_EQ(errors[3].message, "the bound's xmin (1) is greater than its xmax (-1)");
  EXPECT_EQ(errors[4].loc.str(), "scene.rib:5:34");  // the number where a string should be
  // Nothing was read, the request after them was.
  EXPECT_EQ(requests(r->target), (Names{"Sides"}));
}

TEST(Procedural, DynamicLoadWarnsOnceAndIsSkipped) {
  auto r = parse_procedural(
      "Procedural \"DynamicLoad\" [\"hair.so\" \"1 2\"] [-1 1 -1 1 -1 1]\n"
      "Procedural \"DynamicLoad\" [\"fur.so\" \"\"] [-1 1 -1 1 -1 1]\n"
      "Procedural2 \"DynamicLoad\" \"SimpleBound\" \"string dsoname\" [\"x.so\"] \"float[6] bound\" [0 1 0 1 0 1]\n"
      "Sides 2\n",
      "scene.rib");
  EXPECT_TRUE(r->ok) << r->first_error();
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(contains(warnings[0].message, "compiled procedurals cannot be loaded")) << warnings[0].message;
  EXPECT_EQ(warnings[0].loc.line, 1);
  EXPECT_EQ(requests(r->target), (Names{"Sides"}));
  EXPECT_TRUE(r->target.bounds.empty()) << "nothing asked about a procedural that is skipped";
}

TEST(Procedural, AnUnknownProceduralTypeWarnsAndIsSkipped) {
  auto r = parse_procedural("Procedural \"Sprinkles\" [\"x\"] [-1 1 -1 1 -1 1]\nSides 2\n", "scene.rib");
  EXPECT_TRUE(r->ok) << r->first_error();
  ASSERT_EQ(r->warnings().size(), 1u);
  EXPECT_EQ(r->warnings()[0].message, "unknown procedural \"Sprinkles\": skipped");
  EXPECT_EQ(requests(r->target), (Names{"Sides"}));
}

TEST(Procedural, AMissingDelayedArchiveIsAnErrorAtTheRequest) {
  ScratchFolder dir;
  auto r = parse_procedural("WorldBegin\n Procedural \"DelayedReadArchive\" [\"none.rib\"] [0 1 0 1 0 1]\nWorldEnd\n",
                            (dir / "scene.rib").string());
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "cannot open archive \"none.rib\": no such file");
  EXPECT_EQ(errors[0].loc.line, 2);
  EXPECT_EQ(errors[0].loc.column, 2);
  // The attribute block opened for it is closed again.
  EXPECT_EQ(r->target.named("AttributeBegin").size(), r->target.named("AttributeEnd").size());
  EXPECT_EQ(r->target.named("WorldEnd").size(), 1u);
}

// The target declines the procedural (SceneBuilder does in a frame that is not rendered): the
// archive is not read (a missing one is no error) and the program is not started.
TEST(Procedural, ADeclinedProceduralIsNeitherReadNorRun) {
  ScratchFolder dir;
  dir.write_program("gen.sh", "touch '" + (dir / "started").string() + "'\nprintf '\\377'\n");
  ProceduralBound declined;
  declined.wanted = false;
  auto r = parse_procedural(
      "Procedural \"DelayedReadArchive\" [\"none.rib\"] [0 1 0 1 0 1]\n"
      "Procedural \"RunProgram\" [\"gen.sh\" \"\"] [0 1 0 1 0 1]\n",
      (dir / "scene.rib").string(), [&](RibParser& p) { p.set_procedural_folders({dir.str()}); }, declined);
  EXPECT_TRUE(r->ok) << r->first_error();
  EXPECT_TRUE(r->target.calls.empty());
  EXPECT_EQ(r->target.bounds.size(), 2u);
  EXPECT_FALSE(fs::exists(dir / "started"));
}

// RunProgram's detail is the target's area of the bound.
TEST(Procedural, RunProgramGetsTheTargetsRasterAreaAsDetail) {
  ScratchFolder dir;
  // Answers with its request line as a comment record: ArchiveRecord "comment" "<line>".
  dir.write_program("echo.sh", "read line\nprintf 'ArchiveRecord \"comment\" \"%s\"\\n\\377' \"$line\"\n");
  ProceduralBound seen;
  seen.raster_area = 1234.5;
  auto r = parse_procedural(
      "Procedural \"RunProgram\" [\"echo.sh\" \"7 blades\"] [0 1 0 1 0 1]\n", (dir / "scene.rib").string(),
      [&](RibParser& p) { p.set_procedural_folders({dir.str()}); }, seen);
  EXPECT_TRUE(r->ok) << r->first_error();
  const auto records = r->target.named("ArchiveRecord");
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].strings, (std::vector<std::string>{"comment", "1234.5 7 blades"}));
}

// Fuzzing mode (RibParser::allow_archive_files(false)): no file is read, no program started.
TEST(Procedural, FileAccessOffRefusesProceduralsWithoutTouchingTheSystem) {
  ScratchFolder dir;
  dir.write("part.rib", "Sides 1\n");
  dir.write_program("gen.sh", "touch '" + (dir / "started").string() + "'\nprintf 'Sides 1\\n\\377'\n");
  auto r = parse_procedural(
      "Option \"searchpath\" \"procedural\" [\"" + dir.str() +
          "\"]\n"
          "Procedural \"DelayedReadArchive\" [\"part.rib\"] [0 1 0 1 0 1]\n"
          "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" [\"part.rib\"] \"float[6] bound\" "
          "[0 1 0 1 0 1]\n"
          "Procedural \"RunProgram\" [\"gen.sh\" \"\"] [0 1 0 1 0 1]\n"
          "Sides 2\n",
      (dir / "scene.rib").string(), [](RibParser& p) { p.allow_archive_files(false); });
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].message, "DelayedReadArchive \"part.rib\" refused: file access is disabled");
  EXPECT_EQ(errors[1].message, "DelayedReadArchive2 \"part.rib\" refused: file access is disabled");
  EXPECT_EQ(errors[2].message, "RunProgram \"gen.sh\" refused: file access is disabled");
  EXPECT_EQ(errors[2].loc.line, 4);
  EXPECT_FALSE(fs::exists(dir / "started"));
  EXPECT_EQ(r->target.named("Sides").size(), 1u) << "only the scene's own Sides";
  EXPECT_TRUE(r->target.bounds.empty());
}

}  // namespace
}  // namespace darc::test
