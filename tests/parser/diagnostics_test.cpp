// Diagnostics: exact counts, capped showing (per kind and in total, per severity), the kind key,
// and that messages past the caps are not kept.
#include <gtest/gtest.h>

#include "parser/diagnostics.h"
#include "parser/message_budget.h"
#include "recording_target.h"

namespace darc::test {
namespace {

SourceLoc at_line(int line) { return SourceLoc{std::make_shared<const std::string>("t.rib"), line, 1}; }

TEST(MessageKind, NumbersAndQuotedValuesDoNotMakeANewKind) {
  EXPECT_EQ(message_kind("Basis", "unknown basis \"bsline\""), "Basis: unknown basis \"\"");
  EXPECT_EQ(message_kind("Basis", "unknown basis \"bezir\""), message_kind("Basis", "unknown basis \"bsline\""));
  EXPECT_EQ(message_kind("Sides", "Sides must be 1 or 2, found 3"), "Sides: Sides must be # or #, found #");
  EXPECT_EQ(message_kind("Projection", "fov must be in (0, 180) degrees, found -1.5e+02"),
            "Projection: fov must be in (#, #) degrees, found #");
  EXPECT_EQ(message_kind("Curves", "\"P\": point values must come in groups of 3, found 7"),
            "Curves: \"\": point values must come in groups of #, found #");
}

TEST(MessageKind, RequestsAndWordingsStayApart) {
  EXPECT_NE(message_kind("Sides", "found 3"), message_kind("Format", "found 3"));
  EXPECT_NE(message_kind("Curves", "unknown wrap \"x\""), message_kind("Curves", "unknown type \"x\""));
  // Digits inside a word are part of the word, not a number.
  EXPECT_EQ(message_kind("Curves", "\"Pw\" needs 4 floats per vertex"), "Curves: \"\" needs # floats per vertex");
  EXPECT_EQ(message_kind("", "bad token x3."), ": bad token x3.");
}

TEST(Diagnostics, OneMistakeRepeatedIsShownUpToTheKindCapAndCountedExactly) {
  int shown = 0;
  Diagnostics diag([&](const Diagnostic&) { ++shown; });
  const int repeats = 100000;
  for (int i = 0; i < repeats; ++i) diag.error(at_line(i + 1), "Basis", "unknown basis \"b" + std::to_string(i) + "\"");
  EXPECT_EQ(diag.error_count(), repeats);
  EXPECT_EQ(shown, kMaxShownPerKind);
  EXPECT_EQ(diag.all().size(), size_t(kMaxShownPerKind)) << "messages past the cap are not kept";
  EXPECT_EQ(diag.all().back().loc.line, kMaxShownPerKind) << "the first ones are shown";
  const std::vector<std::string> summary = diag.suppression_summary();
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_EQ(summary[0], std::to_string(repeats - kMaxShownPerKind) + " more errors not shown (limit " +
                            std::to_string(kMaxShownPerKind) + " per kind, " + std::to_string(kMaxShownInTotal) +
                            " in total)");
}

TEST(Diagnostics, ManyKindsAreShownUpToTheTotalCap) {
  int shown = 0;
  Diagnostics diag([&](const Diagnostic&) { ++shown; });
  const int kinds = kMaxShownInTotal + 50;
  for (int k = 0; k < kinds; ++k) diag.error(at_line(k + 1), std::string(size_t(k + 1), 'R'), "bad");
  EXPECT_EQ(diag.error_count(), kinds);
  EXPECT_EQ(shown, kMaxShownInTotal);
  ASSERT_EQ(diag.suppression_summary().size(), 1u);
  EXPECT_EQ(diag.suppression_summary()[0].rfind("50 more errors not shown", 0), 0u) << diag.suppression_summary()[0];
}

TEST(Diagnostics, WarningsHaveTheirOwnCapsAndNeverHideErrors) {
  std::vector<Diagnostic> shown;
  Diagnostics diag([&](const Diagnostic& d) { shown.push_back(d); });
  for (int i = 0; i < 1000; ++i) diag.warning(at_line(i + 1), "Display", "display mode \"m\" not supported");
  diag.error(at_line(2000), "Sides", "Sides must be 1 or 2, found 3");
  EXPECT_EQ(diag.warning_count(), 1000);
  EXPECT_EQ(diag.error_count(), 1);
  ASSERT_EQ(shown.size(), size_t(kMaxShownPerKind) + 1);
  EXPECT_EQ(shown.back().severity, Severity::Error);
  const std::vector<std::string> summary = diag.suppression_summary();
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_EQ(summary[0].rfind(std::to_string(1000 - kMaxShownPerKind) + " more warnings not shown", 0), 0u)
      << summary[0];
}

TEST(Diagnostics, NothingPastTheCapsMeansNoSummary) {
  Diagnostics diag([](const Diagnostic&) {});
  diag.error(at_line(1), "Sides", "Sides must be 1 or 2, found 3");
  diag.warning(at_line(2), "Display", "display mode \"m\" not supported");
  EXPECT_TRUE(diag.suppression_summary().empty());
}

TEST(Diagnostics, TheParserReportsEveryRepeatButShowsOnlyTheCap) {
  std::string rib;
  for (int i = 0; i < 500; ++i) rib += "Sides \"two\"\n";
  auto r = parse_rib(rib + "WorldBegin\n");
  EXPECT_EQ(r->diag.error_count(), 500);
  EXPECT_EQ(r->errors().size(), size_t(kMaxShownPerKind));
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u) << "counting past the cap does not stop the parse";
}

}  // namespace
}  // namespace darc::test
