// Conditional RIB (IfBegin / ElseIf / Else / IfEnd): the target sees the requests of the
// branch taken only; conditions see the frame number, options and attributes in effect.
#include <gtest/gtest.h>

#include "recording_target.h"

namespace darc::test {
namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The Sides values the target received, in order: the tests mark branches with them.
std::vector<int> sides_seen(const ParseResult& r) {
  std::vector<int> out;
  for (const RecordedCall& c : r.target.named("Sides")) out.push_back(int(c.numbers[0]));
  return out;
}

TEST(ConditionalRib, OnlyTheFirstTrueBranchRuns) {
  auto r = parse_rib(R"RIB(FrameBegin 2
IfBegin "$Frame == 1"
  Sides 1
ElseIf "$Frame == 2"
  Sides 2
ElseIf "$Frame >= 2"
  Sides 3
Else
  Sides 4
IfEnd
FrameEnd
)RIB");
  EXPECT_TRUE(r->ok);
  EXPECT_TRUE(r->warnings().empty()) << r->warnings()[0].str();
  EXPECT_EQ(sides_seen(*r), std::vector<int>{2});
  EXPECT_EQ(r->target.named("FrameEnd").size(), 1u);
}

TEST(ConditionalRib, ElseRunsWhenNoConditionHolds) {
  auto r = parse_rib("FrameBegin 7 IfBegin \"$Frame < 5\" Sides 1 Else Sides 2 IfEnd FrameEnd");
  EXPECT_EQ(sides_seen(*r), std::vector<int>{2});
}

TEST(ConditionalRib, TheFrameNumberFollowsEachFrame) {
  auto r = parse_rib(R"RIB(FrameBegin 1 IfBegin "$Frame == 1" Sides 1 Else Sides 2 IfEnd FrameEnd
FrameBegin 2 IfBegin "$Frame == 1" Sides 1 Else Sides 2 IfEnd FrameEnd
IfBegin "defined(Frame)" Sides 1 Else Sides 2 IfEnd
)RIB");
  EXPECT_EQ(sides_seen(*r), (std::vector<int>{1, 2, 2})) << "outside a frame $Frame is undefined";
}

TEST(ConditionalRib, NestedBlocksInABranchNotTakenAreSkippedWhole) {
  auto r = parse_rib(R"RIB(IfBegin "0"
  IfBegin "1" Sides 1 Else Sides 2 IfEnd
  Sides 1
Else
  IfBegin "0" Sides 1 ElseIf "1" Sides 2 IfEnd
IfEnd
Sides 1
)RIB");
  EXPECT_TRUE(r->ok);
  EXPECT_EQ(sides_seen(*r), (std::vector<int>{2, 1}));
}

TEST(ConditionalRib, OptionsAndAttributesAreVisibleInTheirScope) {
  auto r = parse_rib(R"RIB(Option "user" "string pass" ["shadow"]
IfBegin "$user:pass == 'shadow'" Sides 1 Else Sides 2 IfEnd
WorldBegin
  AttributeBegin
    Attribute "user" "string pass" ["beauty"]
    IfBegin "$user:pass == 'beauty'" Sides 1 Else Sides 2 IfEnd
    IfBegin "$Option:user:pass == 'shadow'" Sides 1 Else Sides 2 IfEnd
  AttributeEnd
  IfBegin "$user:pass == 'beauty'" Sides 1 Else Sides 2 IfEnd
  IfBegin "$Attribute:user:pass == 'shadow'" Sides 1 Else Sides 2 IfEnd
WorldEnd
)RIB");
  EXPECT_TRUE(r->ok);
  EXPECT_EQ(sides_seen(*r), (std::vector<int>{1, 1, 1, 2, 2}))
      << "the attribute hides the option inside its block only; $Attribute: does not see options";
}

TEST(ConditionalRib, OptionsSetInAFrameEndWithIt) {
  auto r = parse_rib(R"RIB(FrameBegin 1 Option "user" "int quality" [3] FrameEnd
IfBegin "defined(user:quality)" Sides 1 Else Sides 2 IfEnd
)RIB");
  EXPECT_EQ(sides_seen(*r), std::vector<int>{2});
}

TEST(ConditionalRib, PatternMatching) {
  auto r = parse_rib(R"RIB(Attribute "user" "string pass" ["shadow_key"]
IfBegin "$user:pass =~ '^shadow'" Sides 1 Else Sides 2 IfEnd
IfBegin "$user:pass =~ 'fill$'" Sides 1 Else Sides 2 IfEnd
)RIB");
  EXPECT_EQ(sides_seen(*r), (std::vector<int>{1, 2}));
}

TEST(ConditionalRib, AMalformedPatternIsAWarningAtItsRequest) {
  auto r = parse_rib(R"RIB(Attribute "user" "string pass" ["shadow_key"]
IfBegin "$user:pass =~ '^shadow(_key'" Sides 1 Else Sides 2 IfEnd
)RIB");
  EXPECT_TRUE(r->ok);
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].loc.str(), "test.rib:2:1");
  EXPECT_TRUE(contains(warnings[0].message, "missing ): ^shadow(_key")) << warnings[0].message;
  EXPECT_EQ(sides_seen(*r), std::vector<int>{1}) << "the branch is taken, as for any unevaluable condition";
}

TEST(ConditionalRib, AnUnevaluableConditionWarnsOnceAndTakesTheFirstBranchOnly) {
  auto r = parse_rib(R"RIB(FrameBegin 1
IfBegin "$Frame == 1 junk" Sides 1 ElseIf "1" Sides 2 Else Sides 2 IfEnd
IfBegin "$Frame == 1 junk" Sides 1 Else Sides 2 IfEnd
IfBegin "0" Sides 2 ElseIf "frobnicate($Frame)" Sides 1 Else Sides 2 IfEnd
FrameEnd
)RIB");
  EXPECT_TRUE(r->ok) << "a condition darc cannot evaluate is a warning, not an error";
  EXPECT_EQ(sides_seen(*r), (std::vector<int>{1, 1, 1}));
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 2u) << "one warning per expression";
  EXPECT_EQ(warnings[0].request, "IfBegin");
  EXPECT_EQ(warnings[0].loc.str(), "test.rib:2:1");
  EXPECT_TRUE(contains(warnings[0].message, "cannot evaluate \"$Frame == 1 junk\"")) << warnings[0].message;
  EXPECT_EQ(warnings[1].request, "ElseIf");
}

TEST(ConditionalRib, UnbalancedBlocksAreErrors) {
  {
    auto r = parse_rib("Sides 1\nIfEnd\nElse\nElseIf \"1\"\nSides 2\n");
    const auto errors = r->errors();
    ASSERT_EQ(errors.size(), 3u);
    EXPECT_EQ(errors[0].message, "IfEnd without IfBegin");
    EXPECT_EQ(errors[0].loc.str(), "test.rib:2:1");
    EXPECT_EQ(errors[1].message, "Else without IfBegin");
    EXPECT_EQ(errors[2].message, "ElseIf without IfBegin");
    EXPECT_EQ(sides_seen(*r), (std::vector<int>{1, 2}));
  }
  {
    auto r = parse_rib("IfBegin \"1\"\n  IfBegin \"0\"\nIfEnd\nSides 1\n");
    const auto errors = r->errors();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].loc.str(), "test.rib:1:1") << "the outer block is the one left open";
    EXPECT_TRUE(contains(errors[0].message, "never closed")) << errors[0].message;
    EXPECT_EQ(sides_seen(*r), std::vector<int>{1});
  }
  {
    auto r = parse_rib("IfBegin \"0\" Else Sides 1 Else Sides 2 ElseIf \"1\" Sides 3 IfEnd");
    const auto errors = r->errors();
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_TRUE(contains(errors[0].message, "Else after Else")) << errors[0].message;
    EXPECT_TRUE(contains(errors[1].message, "ElseIf after Else")) << errors[1].message;
    EXPECT_EQ(sides_seen(*r), (std::vector<int>{1, 2, 3})) << "the erroneous requests change nothing";
  }
}

TEST(ConditionalRib, AMalformedIfBeginIsAnErrorAndStillOpensItsBlock) {
  auto r = parse_rib("IfBegin 3\nSides 1\nElse\nSides 2\nIfEnd\nSides 1\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].request, "IfBegin");
  EXPECT_EQ(sides_seen(*r), (std::vector<int>{1, 1}));
}

TEST(ConditionalRib, StrayArgumentsAfterElseOrIfEndAreErrorsThatKeepTheBlock) {
  auto r = parse_rib("IfBegin \"0\" Sides 1 Else 3 Sides 2 IfEnd [1] Sides 1");
  EXPECT_EQ(r->errors().size(), 2u);
  EXPECT_EQ(sides_seen(*r), (std::vector<int>{2, 1}));
}

TEST(ConditionalRib, BlocksMustCloseInTheTextThatOpenedThem) {
  // An inline archive's body is a text of its own: its IfBegin cannot be closed after it.
  auto r = parse_rib("ArchiveBegin \"a\" IfBegin \"1\" Sides 1 ArchiveEnd\nReadArchive \"a\"\nIfEnd\n");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].loc.str(), "test.rib:1:18");
  EXPECT_TRUE(contains(errors[0].message, "never closed")) << errors[0].message;
  EXPECT_EQ(errors[1].message, "IfEnd without IfBegin");
}

TEST(ConditionalRib, SkippedRequestsAreNotRead) {
  // A request with an error in a branch not taken is not reported: it is not run.
  auto r = parse_rib("IfBegin \"0\" Translate 1 \"two\" 3 Sides 9 IfEnd Sides 1");
  EXPECT_TRUE(r->ok);
  EXPECT_EQ(sides_seen(*r), std::vector<int>{1});
}

}  // namespace
}  // namespace darc::test
