// Error positions, messages, recovery, and robustness against malformed input.
#include <gtest/gtest.h>

#include <random>

#include "recording_target.h"

namespace darc::test {
namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(RibParserErrors, ErrorCarriesFileLineColumnAndRequest) {
  auto r = parse_rib("WorldBegin\nTranslate 1 \"two\" 3\nWorldEnd\n", "scene.rib");
  EXPECT_FALSE(r->ok);
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].request, "Translate");
  EXPECT_EQ(errors[0].loc.str(), "scene.rib:2:13");  // the offending string
  EXPECT_TRUE(contains(errors[0].message, "expected")) << errors[0].message;
  EXPECT_TRUE(contains(errors[0].message, "string \"two\"")) << errors[0].message;
  // Recovery: WorldEnd still arrives, the bad Translate does not.
  EXPECT_EQ(r->target.named("WorldEnd").size(), 1u);
  EXPECT_TRUE(r->target.named("Translate").empty());
}

TEST(RibParserErrors, TwoErrorsAreBothReportedAndLaterRequestsArrive) {
  auto r = parse_rib(
      "Format 320.5 240 1\n"
      "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 0 1 1 1 2]\n"
      "Sphere 1 -1 1 360\n");
  const auto errors = r->errors();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].loc.line, 1);
  EXPECT_EQ(errors[0].loc.column, 8);
  EXPECT_TRUE(contains(errors[0].message, "integer")) << errors[0].message;
  EXPECT_EQ(errors[1].loc.line, 2);
  EXPECT_EQ(errors[1].loc.column, 35);  // the "P" token
  EXPECT_EQ(errors[1].message, "\"P\": point values must come in groups of 3, found 7");
  EXPECT_EQ(r->target.named("Sphere").size(), 1u);
}

TEST(RibParserErrors, MissingArgumentsStopAtTheNextRequest) {
  auto r = parse_rib("Translate 1 2\nWorldBegin\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].loc.line, 2);  // found the request name WorldBegin
  EXPECT_TRUE(contains(r->errors()[0].message, "WorldBegin")) << r->errors()[0].message;
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u);
}

TEST(RibParserErrors, TypeMismatchesInParameterLists) {
  auto r = parse_rib(
      "Surface \"plastic\" \"Ka\" \"high\"\nSurface \"plastic\" \"texturename\" [1]\n"
      "Surface \"plastic\" \"Ka\" [1 \"x\"]\nSurface \"plastic\" 5\nSurface \"plastic\" \"Ka\"\n"
      "Declare \"n\" \"uniform int\"\nSurface \"s\" \"n\" 2.5\nWorldBegin");
  EXPECT_EQ(r->errors().size(), 6u);
  for (const Diagnostic& d : r->errors()) EXPECT_EQ(d.request, "Surface") << d.str();
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u);
}

TEST(RibParserErrors, TrailingArgumentsAreAnError) {
  auto r = parse_rib("Translate 1 2 3 4\nScreenWindow [0 1 0 1 5]\nWorldBegin");
  EXPECT_EQ(r->errors().size(), 2u);
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u);
}

TEST(RibParserErrors, InvalidDeclareIsAnError) {
  auto r = parse_rib("Declare \"x\" \"uniform flot\"\nDeclare \"y\" \"varying float\"");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].request, "Declare");
  EXPECT_EQ(r->target.named("Declare").size(), 1u);
}

TEST(RibParserErrors, UnknownRequestWarnsOncePerNameAndSkipsItsArguments) {
  auto r = parse_rib("Foo 1 2 [3] \"x\"\nFoo 4\nBar\nBlobby 1 [1001 0] [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] [\"\"]\nWorldBegin");
  EXPECT_TRUE(r->ok);
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0].message, "unknown request \"Foo\": skipped");
  EXPECT_EQ(warnings[0].loc.line, 1);
  EXPECT_EQ(warnings[1].message, "unknown request \"Bar\": skipped");
  EXPECT_TRUE(contains(warnings[2].message, "Blobby"));
  ASSERT_EQ(r->target.calls.size(), 1u);
  EXPECT_EQ(r->target.calls[0].request, "WorldBegin");
}

TEST(RibParserErrors, StrayValuesBeforeARequestAreAnError) {
  auto r = parse_rib("1 2 3 WorldBegin ] [ WorldEnd");
  EXPECT_EQ(r->errors().size(), 2u);  // the stray numbers, and "]" after WorldBegin (which is dropped)
  ASSERT_EQ(r->target.calls.size(), 1u);
  EXPECT_EQ(r->target.calls[0].request, "WorldEnd");
}

TEST(RibParserErrors, UnbalancedBrackets) {
  auto r = parse_rib("Color [1 0 0\nSphere 1 -1 1 360 \"Cs\" [1 0 0\nWorldBegin\nPolygon \"P\" ]\nWorldEnd");
  EXPECT_EQ(r->errors().size(), 3u);
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u);
  EXPECT_EQ(r->target.named("WorldEnd").size(), 1u);
}

TEST(RibParserErrors, OutOfRangeNumbersAndNanSpellings) {
  auto r = parse_rib("Translate 1e999 0 0\nScale -nan 1 1\nRotate 1e39 0 0 1\nWorldBegin");
  EXPECT_EQ(r->errors().size(), 3u);
  for (const Diagnostic& d : r->errors())
    EXPECT_EQ(d.loc.column, d.request == "Scale" ? 7 : (d.request == "Rotate" ? 8 : 11));
  EXPECT_EQ(r->target.calls.size(), 1u);
}

TEST(RibParserErrors, BinaryRibIsReportedAtItsPositionAndReadingStops) {
  std::string text = "WorldBegin\nSphere 1 -1 1 360\n";
  text += '\x80';
  text += "\x05 garbage\nWorldEnd\n";
  auto r = parse_rib(text, "bin.rib");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].message, "binary RIB is not supported");
  EXPECT_EQ(r->errors()[0].loc.str(), "bin.rib:3:1");
  EXPECT_TRUE(r->target.named("WorldEnd").empty());
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u);
  // The Sphere's parameter list ran into the binary byte, so the Sphere is not delivered.
  EXPECT_TRUE(r->target.named("Sphere").empty());
}

TEST(RibParserErrors, UnterminatedStringIsReportedAtItsStart) {
  auto r = parse_rib("WorldBegin\nSurface \"plastic\nWorldEnd\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].loc.line, 2);
  EXPECT_EQ(r->errors()[0].loc.column, 9);
  EXPECT_TRUE(contains(r->errors()[0].message, "unterminated string"));
}

TEST(RibParserErrors, RibErrorFromTheTargetIsReportedAtTheRequest) {
  struct Refusing : RecordingTarget {
    void primitive(const PrimitiveRequest&, const ParamList&, const SourceLoc&) override {
      throw RibError("sphere radius must be positive");
    }
  } target;
  Diagnostics diag([](const Diagnostic&) {});
  RibParser parser(target, diag);
  EXPECT_FALSE(parser.parse_string("WorldBegin\n  Sphere -1 -1 1 360\nWorldEnd", "t.rib"));
  ASSERT_EQ(diag.error_count(), 1);
  EXPECT_EQ(diag.all()[0].str(), "t.rib:2:3: error: Sphere: sphere radius must be positive");
  EXPECT_EQ(target.named("WorldEnd").size(), 1u);
}

// Random bytes, truncations and shuffled fragments: the parser must finish without crashing.
TEST(RibParserErrors, SurvivesRandomAndTruncatedInput) {
  const std::string good =
      "version 3.03\nFormat 320 240 1\nProjection \"perspective\" \"fov\" [30]\nWorldBegin\n"
      "Basis \"catmull-rom\" 1 \"catmull-rom\" 1\nCurves \"cubic\" [4] \"nonperiodic\" \"P\" [0 0 0 1 1 1 2 2 2 3 3 3] "
      "\"width\" [.1 .2]\nLightSource \"spotlight\" 1 \"coneangle\" 0.5\nWorldEnd\n";
  std::mt19937 rng(12345);  // fixed seed: the test is deterministic
  for (size_t cut = 0; cut <= good.size(); cut += 7) (void)parse_rib(good.substr(0, cut));
  const std::string alphabet = "[]\"#\\.-+e0123456789 \n\rABCPWorldBegin\t\x01\x7f\xff";
  for (int trial = 0; trial < 300; ++trial) {
    std::string text;
    const size_t length = rng() % 200;
    for (size_t i = 0; i < length; ++i) {
      text += (trial % 2 == 0) ? static_cast<char>(rng() & 0xff) : alphabet[rng() % alphabet.size()];
    }
    auto r = parse_rib(text);
    EXPECT_EQ(r->ok, r->diag.error_count() == 0);
  }
  // Huge counts and deep arrays.
  (void)parse_rib("Curves \"linear\" [" + std::string(20000, '[') + "] \"x\"");
  (void)parse_rib("Declare \"a\" \"float[2147483647]\" Surface \"s\" \"a\" [1]");
  (void)parse_rib("Format 1e30 1e30 1\nFormat -2147483649 1 1\nSides 99999999999");
}

}  // namespace
}  // namespace darc::test
