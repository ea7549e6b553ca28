// Inline archives (ArchiveBegin / ArchiveEnd): the body is kept, not run, and each ReadArchive
// of its name replays it, with errors at their positions in the original text. (An inline
// archive against a file of the same name: rib_files_test.cpp.)
#include <gtest/gtest.h>

#include "recording_target.h"

namespace darc::test {
namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(InlineArchive, TheBodyRunsAtEachReadArchiveOnly) {
  auto r = parse_rib(R"RIB(ArchiveBegin "ball"
  Sphere 1 -1 1 360
ArchiveEnd
WorldBegin
  ReadArchive "ball"
  Translate 1 0 0
  ReadArchive "ball"
WorldEnd
)RIB");
  EXPECT_TRUE(r->ok);
  EXPECT_TRUE(r->warnings().empty()) << r->warnings()[0].str();
  ASSERT_EQ(r->target.calls.size(), 5u);
  EXPECT_EQ(r->target.calls[0].request, "WorldBegin") << "nothing of the body runs where it is defined";
  EXPECT_EQ(r->target.calls[1].request, "Sphere");
  EXPECT_EQ(r->target.calls[1].loc.str(), "test.rib:2:3") << "replayed requests keep their original positions";
  EXPECT_EQ(r->target.calls[3].request, "Sphere");
  EXPECT_EQ(r->target.calls[3].loc.str(), "test.rib:2:3");
}

TEST(InlineArchive, ErrorsInAReplayPointIntoTheArchiveBody) {
  auto r =
      parse_rib("ArchiveBegin \"a\" Sides 1 Translate 1 \"two\" 3 ArchiveEnd\nReadArchive \"a\"\nReadArchive \"a\"\n");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u) << "one error per replay";
  EXPECT_EQ(errors[0].request, "Translate");
  EXPECT_EQ(errors[0].loc.str(), "test.rib:1:38");
  EXPECT_EQ(errors[1].loc.str(), "test.rib:1:38");
  EXPECT_EQ(r->target.named("Sides").size(), 2u);
}

TEST(InlineArchive, ConditionsInsideAreEvaluatedAtEachReplay) {
  auto r = parse_rib(R"RIB(ArchiveBegin "shading"
  IfBegin "$user:pass == 'shadow'" Surface "null" Else Surface "plastic" IfEnd
ArchiveEnd
Attribute "user" "string pass" ["shadow"]
ReadArchive "shading"
Attribute "user" "string pass" ["beauty"]
ReadArchive "shading"
)RIB");
  EXPECT_TRUE(r->ok);
  const auto surfaces = r->target.named("Surface");
  ASSERT_EQ(surfaces.size(), 2u);
  EXPECT_EQ(surfaces[0].strings[0], "null");
  EXPECT_EQ(surfaces[1].strings[0], "plastic");
}

TEST(InlineArchive, NestedDefinitionsAreMadeWhenTheOuterOneIsReplayed) {
  auto r = parse_rib(R"RIB(ArchiveBegin "outer"
  ArchiveBegin "inner" Sides 2 ArchiveEnd
  Sides 1
ArchiveEnd
ReadArchive "outer"
ReadArchive "inner"
)RIB");
  EXPECT_TRUE(r->ok) << r->errors()[0].str();
  const auto sides = r->target.named("Sides");
  ASSERT_EQ(sides.size(), 2u);
  EXPECT_EQ(sides[0].numbers[0], 1);
  EXPECT_EQ(sides[1].numbers[0], 2);
}

TEST(InlineArchive, ALaterDefinitionReplacesAnEarlierOne) {
  auto r = parse_rib(
      "ArchiveBegin \"a\" Sides 1 ArchiveEnd ReadArchive \"a\" ArchiveBegin \"a\" Sides 2 ArchiveEnd "
      "ReadArchive \"a\"");
  const auto sides = r->target.named("Sides");
  ASSERT_EQ(sides.size(), 2u);
  EXPECT_EQ(sides[1].numbers[0], 2);
}

TEST(InlineArchive, RecursionIsAnErrorNotAHang) {
  auto r = parse_rib(
      "ArchiveBegin \"a\" Sides 1 ReadArchive \"b\" ArchiveEnd\n"
      "ArchiveBegin \"b\" Sides 2 ReadArchive \"a\" ArchiveEnd\n"
      "ReadArchive \"a\"\nSides 1\n");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_TRUE(contains(errors[0].message, "includes itself")) << errors[0].message;
  EXPECT_EQ(errors[0].loc.str(), "test.rib:2:26") << "at the ReadArchive that closes the cycle";
  EXPECT_EQ(r->target.named("Sides").size(), 3u);
}

TEST(InlineArchive, ArchivesThatReadEachOtherManyTimesOverStopAtTheCap) {
  // Each level reads the one below it four times: 4^12 reads in all, unless capped.
  std::string rib = "ArchiveBegin \"a0\" Sides 1 ArchiveEnd\n";
  for (int i = 1; i <= 12; ++i) {
    const std::string below = "ReadArchive \"a" + std::to_string(i - 1) + "\" ";
    rib += "ArchiveBegin \"a" + std::to_string(i) + "\" " + below + below + below + below + "ArchiveEnd\n";
  }
  rib += "ReadArchive \"a12\"\nSides 2\n";
  auto r = parse_rib(rib);
  EXPECT_FALSE(r->ok);
  ASSERT_FALSE(r->errors().empty());
  EXPECT_TRUE(contains(r->errors()[0].message, "not read: this run has read inline archives 250000 times"))
      << r->errors()[0].message;
  const auto sides = r->target.named("Sides");
  ASSERT_FALSE(sides.empty());
  EXPECT_LT(sides.size(), 250000u);
  EXPECT_EQ(sides.back().numbers[0], 2) << "the requests after it are read";
}

TEST(InlineArchive, AnUnclosedArchiveIsAnErrorAtItsArchiveBegin) {
  auto r = parse_rib("Sides 1\nArchiveBegin \"a\"\nSides 2\n");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].request, "ArchiveBegin");
  EXPECT_EQ(errors[0].loc.str(), "test.rib:2:1");
  EXPECT_EQ(errors[0].message, "archive \"a\" is never closed (ArchiveEnd missing)");
  EXPECT_EQ(r->target.named("Sides").size(), 1u);
}

TEST(InlineArchive, AnUnterminatedStringThatSwallowsArchiveEndIsNamed) {
  auto r = parse_rib("ArchiveBegin \"a\"\nSurface \"plastic\nArchiveEnd\n");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].message, "unterminated string");
  EXPECT_EQ(errors[0].loc.str(), "test.rib:2:9");
  EXPECT_TRUE(contains(errors[1].message, "never closed")) << errors[1].message;
}

TEST(InlineArchive, AStrayArchiveEndIsAnError) {
  auto r = parse_rib("ArchiveEnd\nSides 1\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message, "ArchiveEnd without ArchiveBegin");
  EXPECT_EQ(r->target.named("Sides").size(), 1u);
}

TEST(InlineArchive, AnUnknownNameStillFallsBackToFiles) {
  auto r = parse_rib("ArchiveBegin \"a\" Sides 1 ArchiveEnd\nReadArchive \"b\"\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message, "cannot open archive \"b\": no such file");
}

TEST(InlineArchive, ArchiveBeginInABranchNotTakenDefinesNothing) {
  auto r = parse_rib("IfBegin \"0\" ArchiveBegin \"a\" Sides 1 ArchiveEnd IfEnd\nReadArchive \"a\"\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message, "cannot open archive \"a\": no such file");
}

}  // namespace
}  // namespace darc::test
