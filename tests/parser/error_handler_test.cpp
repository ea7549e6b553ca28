// The RI ErrorHandler: "print" (the default), "ignore", "abort", applied by the parser from the
// next request on, and fixed by the command line (--strict).
#include <gtest/gtest.h>

#include "parser/diagnostics.h"
#include "parser/error_handler.h"
#include "recording_target.h"

namespace darc::test {
namespace {

SourceLoc at_line(int line) { return SourceLoc{std::make_shared<const std::string>("t.rib"), line, 1}; }

TEST(ErrorHandler, NamesAreTheRiOnes) {
  EXPECT_EQ(error_handler_named("ignore"), ErrorHandler::Ignore);
  EXPECT_EQ(error_handler_named("print"), ErrorHandler::Print);
  EXPECT_EQ(error_handler_named("abort"), ErrorHandler::Abort);
  EXPECT_EQ(error_handler_named("Abort"), std::nullopt);
  EXPECT_STREQ(to_string(ErrorHandler::Abort), "abort");
}

TEST(ErrorHandler, IgnoreShowsNothingAndCountsEverything) {
  int shown = 0;
  Diagnostics diag([&](const Diagnostic&) { ++shown; });
  diag.set_handler(ErrorHandler::Ignore);
  diag.error(at_line(1), "Sides", "Sides must be 1 or 2, found 3");
  diag.warning(at_line(2), "Display", "display mode \"m\" not supported");
  EXPECT_EQ(shown, 0) << "RI's ignore handler gets warnings too";
  EXPECT_TRUE(diag.all().empty());
  EXPECT_EQ(diag.error_count(), 1);
  EXPECT_EQ(diag.warning_count(), 1);
  EXPECT_EQ(diag.frame_errors().count, 1);
  EXPECT_EQ(diag.frame_errors().first, "t.rib:1:1: error: Sides: Sides must be 1 or 2, found 3")
      << "the frame still records its errors";
  EXPECT_TRUE(diag.suppression_summary().empty()) << "ignored messages are not counted as held back by the caps";
  EXPECT_FALSE(diag.aborted());
}

TEST(ErrorHandler, AbortStopsAtTheFirstErrorButNotAtAWarning) {
  int shown = 0;
  Diagnostics diag([&](const Diagnostic&) { ++shown; });
  diag.set_handler(ErrorHandler::Abort);
  diag.warning(at_line(1), "Display", "display mode \"m\" not supported");
  EXPECT_FALSE(diag.aborted());
  diag.error(at_line(2), "Sides", "Sides must be 1 or 2, found 3");
  EXPECT_TRUE(diag.aborted());
  EXPECT_EQ(shown, 2) << "abort prints the error, as RI's RiErrorAbort does";
}

TEST(ErrorHandler, AFixedHandlerRefusesChanges) {
  Diagnostics diag([](const Diagnostic&) {});
  diag.fix_handler(ErrorHandler::Abort);
  EXPECT_FALSE(diag.set_handler(ErrorHandler::Ignore));
  EXPECT_EQ(diag.handler(), ErrorHandler::Abort);
}

TEST(ErrorHandler, TheParserAppliesItFromTheNextRequestOn) {
  auto r = parse_rib(
      "Sides \"one\"\n"
      "ErrorHandler \"ignore\"\n"
      "Sides \"two\"\n"
      "ErrorHandler \"print\"\n"
      "Sides \"three\"\n");
  EXPECT_EQ(r->diag.error_count(), 3);
  ASSERT_EQ(r->errors().size(), 2u) << "the error under \"ignore\" is counted, not shown";
  EXPECT_EQ(r->errors()[0].loc.line, 1);
  EXPECT_EQ(r->errors()[1].loc.line, 5);
  // The target sees it as a request without effect on the image, so RibWriter writes it back.
  ASSERT_EQ(r->target.named("ErrorHandler").size(), 2u);
  EXPECT_EQ(r->target.named("ErrorHandler")[0].strings, std::vector<std::string>{"ignore"});
}

TEST(ErrorHandler, UnderAbortTheParserReadsNothingAfterTheFirstError) {
  auto r = parse_rib(
      "ErrorHandler \"abort\"\n"
      "WorldBegin\n"
      "Sides \"one\"\n"
      "Sides \"two\"\n"
      "WorldEnd\n");
  EXPECT_TRUE(r->diag.aborted());
  EXPECT_EQ(r->diag.error_count(), 1);
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u);
  EXPECT_TRUE(r->target.named("WorldEnd").empty()) << "the frame never ends, so nothing is rendered for it";
}

TEST(ErrorHandler, AnUnknownNameWarnsAndKeepsTheHandler) {
  auto r = parse_rib("ErrorHandler \"abort\"\nErrorHandler \"explode\"\nSides \"one\"\nSides \"two\"\n");
  ASSERT_EQ(r->warnings().size(), 1u);
  EXPECT_EQ(r->warnings()[0].message,
            "unknown handler \"explode\" (expected ignore, print or abort): keeping \"abort\"");
  EXPECT_EQ(r->warnings()[0].loc.line, 2);
  EXPECT_TRUE(r->diag.aborted());
  EXPECT_EQ(r->diag.error_count(), 1);
}

TEST(ErrorHandler, TheCommandLineOverridesTheRib) {
  RecordingTarget target;
  std::vector<Diagnostic> shown;
  Diagnostics diag([&](const Diagnostic& d) { shown.push_back(d); });
  diag.fix_handler(ErrorHandler::Abort);
  RibParser parser(target, diag);
  parser.parse_string("ErrorHandler \"ignore\"\nErrorHandler \"print\"\nSides \"one\"\nWorldBegin\n", "t.rib");
  EXPECT_TRUE(diag.aborted());
  EXPECT_TRUE(target.named("WorldBegin").empty());
  ASSERT_EQ(shown.size(), 2u) << "one warning for the refused ErrorHandlers, then the error";
  EXPECT_EQ(shown[0].message, "ErrorHandler \"ignore\" ignored: the command line fixed the handler to \"abort\"");
  EXPECT_EQ(shown[1].severity, Severity::Error);
}

}  // namespace
}  // namespace darc::test
