// What a diagnostic may repeat of the RIB: quoted values cut to a short excerpt, control bytes
// escaped, a whole message capped; and an archive that does not begin as RIB is refused whole,
// with nothing of it quoted.
#include <gtest/gtest.h>

#include "parser/message_excerpt.h"
#include "procedural_test_util.h"

namespace darc::test {
namespace {

TEST(MessageExcerpt, ShortValuesStayWhole) {
  EXPECT_EQ(bounded_message("unknown basis \"bsline\""), "unknown basis \"bsline\"");
  EXPECT_EQ(excerpt(std::string(kMaxQuotedBytes, 'a')), std::string(kMaxQuotedBytes, 'a'));
}

TEST(MessageExcerpt, LongValuesAreCutInTheMiddle) {
  const std::string secret = std::string(300, 's') + "TAIL";
  const std::string bounded = bounded_message("unknown request \"" + secret + "\": skipped");
  EXPECT_EQ(bounded, "unknown request \"" + std::string(kExcerptHeadBytes, 's') + "..." +
                         std::string(kExcerptTailBytes - 4, 's') + "TAIL\": skipped");
}

TEST(MessageExcerpt, ControlBytesAreEscapedEverywhere) {
  EXPECT_EQ(bounded_message("a \"\x1b[2Jb\" c\x07"), "a \"\\x1b[2Jb\" c\\x07");
  EXPECT_EQ(excerpt("x\ny"), "x\\x0ay");
}

TEST(MessageExcerpt, AnUnpairedQuoteBoundsTheRest) {
  const std::string bounded = bounded_message("value \"" + std::string(500, 'v'));
  EXPECT_EQ(bounded.size(), std::string("value \"").size() + kExcerptHeadBytes + 3 + kExcerptTailBytes);
}

TEST(MessageExcerpt, AWholeMessageIsCapped) {
  std::string message;
  for (int i = 0; i < 100; ++i) message += "word \"value\" ";
  EXPECT_EQ(bounded_message(message).size(), kMaxMessageBytes + 3);
}

// Every diagnostic goes through the bound, the request name included, and so does the frame's
// first error (what the image records).
TEST(MessageExcerpt, DiagnosticsAreBounded) {
  Diagnostics diag{[](const Diagnostic&) {}};
  const std::string long_name(300, 'R');
  diag.error(SourceLoc{}, long_name, "unknown basis \"" + std::string(300, 'b') + "\"");
  ASSERT_EQ(diag.all().size(), 1u);
  EXPECT_EQ(diag.all()[0].request.size(), kExcerptHeadBytes + 3 + kExcerptTailBytes);
  EXPECT_EQ(diag.all()[0].message.size(), std::string("unknown basis \"\"").size() + kExcerptHeadBytes + 3 +
                                               kExcerptTailBytes)
      << diag.all()[0].message;
  EXPECT_LT(diag.frame_errors().first.size(), 2 * kMaxQuotedBytes + 60) << diag.frame_errors().first;
}

// A file that is not RIB, named as an archive: refused at the request, and no token of it
// appears in any message.
TEST(MessageExcerpt, AnArchiveThatIsNotRibIsRefusedWhole) {
  ScratchFolder dir;
  dir.write("passwd", "root:x:0:0:root:/root:/bin/bash\nalice:x:1000:1000:Alice:/home/alice:/bin/sh\n");
  dir.write("key", "-----BEGIN OPENSSH PRIVATE KEY-----\nb3BlbnNzaC1rZXktdjEAAAAABG5vbmUAAAAEbm9uZQ\n");
  dir.write("environ", "HOME=/home/alice\nTOKEN=hunter2\n");
  dir.write("string", "\"hunter2\"\n");
  for (const std::string name : {"passwd", "key", "environ", "string"}) {
    SCOPED_TRACE(name);
    auto r = parse_procedural("ReadArchive \"" + name + "\"\nSides 2\n", (dir / "scene.rib").string());
    ASSERT_EQ(r->diag.all().size(), 1u) << "one error, no warning about its tokens";
    const Diagnostic& d = r->diag.all()[0];
    EXPECT_EQ(d.loc.line, 1);
    EXPECT_EQ(d.message, "cannot read archive \"" + name +
                             "\": it does not begin with a RIB request, so it is not RIB text (or is binary RIB, "
                             "which is not supported); nothing of it is read");
    for (const char* secret : {"root", "alice", "BEGIN", "b3Bl", "hunter2", "HOME"})
      EXPECT_EQ(d.str().find(secret), std::string::npos) << d.str();
    EXPECT_EQ(r->target.named("Sides").size(), 1u);
  }
}

// Comments, white space and an empty file are RIB; so is a file that begins with any RenderMan
// request, known to darc or not.
TEST(MessageExcerpt, RibArchivesStillRead) {
  ScratchFolder dir;
  dir.write("commented.rib", "##RenderMan RIB\n# a comment\n\n  Sides 1\n");
  dir.write("empty.rib", "# nothing\n");
  dir.write("version.rib", "version 3.04\nSides 1\n");
  dir.write("unsupported.rib", "Hyperboloid 0 0 0 1 1 1 360\nSides 1\n");
  for (const std::string name : {"commented.rib", "empty.rib", "version.rib", "unsupported.rib"}) {
    SCOPED_TRACE(name);
    auto r = parse_procedural("ReadArchive \"" + name + "\"\n", (dir / "scene.rib").string());
    EXPECT_TRUE(r->ok) << r->first_error();
  }
}

}  // namespace
}  // namespace darc::test
