// Argument forms of each request, as real files write them.
#include <gtest/gtest.h>

#include "recording_target.h"

namespace darc::test {
namespace {

using Numbers = std::vector<double>;
using Strings = std::vector<std::string>;

// Parses `text`, expects no diagnostics, and returns the calls.
std::vector<RecordedCall> clean_calls(const std::string& text) {
  auto r = parse_rib(text);
  EXPECT_TRUE(r->ok) << text;
  for (const Diagnostic& d : r->diag.all()) ADD_FAILURE() << d.str();
  return r->target.calls;
}

RecordedCall single_call(const std::string& text) {
  const auto calls = clean_calls(text);
  EXPECT_EQ(calls.size(), 1u) << text;
  return calls.empty() ? RecordedCall{} : calls.front();
}

TEST(RibParserRequests, OptionsWithFixedArguments) {
  const auto calls = clean_calls(
      "version 3.04999995\nFormat 320.0 240 1\nFrameAspectRatio 1.333\nClipping 1 1000\n"
      "PixelFilter \"gaussian\" 2 2\nExposure 1 2.2\nQuantize \"rgba\" 255 0 255 0.5\n");
  ASSERT_EQ(calls.size(), 7u);
  EXPECT_EQ(calls[0].numbers, Numbers{3.04999995});
  EXPECT_EQ(calls[1].numbers, (Numbers{320, 240, 1}));
  EXPECT_EQ(calls[3].numbers, (Numbers{1, 1000}));
  EXPECT_EQ(calls[4].strings, Strings{"gaussian"});
  EXPECT_EQ(calls[6].numbers, (Numbers{255, 0, 255, 0.5}));
}

TEST(RibParserRequests, BracketOptionalForms) {
  for (const std::string args : {"-1 1 -.75 .75", "[-1 1 -.75 .75]"}) {
    EXPECT_EQ(single_call("ScreenWindow " + args).numbers, (Numbers{-1, 1, -0.75, 0.75}));
    EXPECT_EQ(single_call("CropWindow " + args).numbers, (Numbers{-1, 1, -0.75, 0.75}));
  }
  EXPECT_EQ(single_call("Color 1 0 .5").numbers, single_call("Color [1 0 .5]").numbers);
  EXPECT_EQ(single_call("Opacity [1 1 1]").numbers, (Numbers{1, 1, 1}));
  EXPECT_EQ(single_call("PixelSamples 4.000000 4.000000").numbers, single_call("PixelSamples [4 4]").numbers);
  const std::string m = "1 0 0 0 0 1 0 0 0 0 1 0 -20 20 -30 1";
  const RecordedCall bracketed = single_call("Transform [" + m + "]");
  EXPECT_EQ(bracketed.numbers, single_call("Transform " + m).numbers);
  EXPECT_EQ(bracketed.numbers[12], -20);
  EXPECT_EQ(single_call("ConcatTransform " + m).numbers, bracketed.numbers);
}

TEST(RibParserRequests, BlocksAndTransforms) {
  const auto calls = clean_calls(
      "FrameBegin 1 WorldBegin AttributeBegin TransformBegin Identity Translate 1 2 3 Rotate -37 1 0 0 "
      "Scale -1 1 1 Perspective 45 CoordinateSystem \"cam\" CoordSysTransform \"cam\" TransformEnd AttributeEnd "
      "WorldEnd FrameEnd");
  const Strings expected = {"FrameBegin",        "WorldBegin",   "AttributeBegin", "TransformBegin", "Identity",
                            "Translate",         "Rotate",       "Scale",          "Perspective",    "CoordinateSystem",
                            "CoordSysTransform", "TransformEnd", "AttributeEnd",   "WorldEnd",       "FrameEnd"};
  ASSERT_EQ(calls.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(calls[i].request, expected[i]);
  EXPECT_EQ(calls[0].numbers, Numbers{1});
  EXPECT_EQ(calls[6].numbers, (Numbers{-37, 1, 0, 0}));
  EXPECT_EQ(calls[9].strings, Strings{"cam"});
}

TEST(RibParserRequests, LightHandlesAreIntegersOrStrings) {
  EXPECT_EQ(single_call("LightSource \"pointlight\" 1 \"intensity\" 3000").strings, (Strings{"pointlight", "1"}));
  EXPECT_EQ(single_call("LightSource \"distantlight\" \"Light1\"").strings, (Strings{"distantlight", "Light1"}));
  EXPECT_EQ(single_call("AreaLightSource \"arealight\" 2.0").strings, (Strings{"arealight", "2"}));
  const RecordedCall illum = single_call("Illuminate 3 0");
  EXPECT_EQ(illum.strings, Strings{"3"});
  EXPECT_EQ(illum.numbers, Numbers{0});
  EXPECT_EQ(single_call("ObjectBegin \"tree\"").strings, Strings{"tree"});
  EXPECT_EQ(single_call("ObjectInstance 5").strings, Strings{"5"});
}

TEST(RibParserRequests, BasisByNameOrMatrix) {
  const RecordedCall named = single_call("Basis \"bezier\" 1 \"catmull-rom\" 1");
  EXPECT_EQ(named.strings, (Strings{"bezier", "catmull-rom"}));
  EXPECT_EQ(named.numbers[16], 1);
  const RecordedCall matrix = single_call("Basis [-1 3 -3 1 3 -6 3 0 -3 3 0 0 1 0 0 0] 3 \"b-spline\" 1");
  EXPECT_EQ(matrix.strings, (Strings{"", "b-spline"}));
  EXPECT_EQ(matrix.numbers[0], -1);
  EXPECT_EQ(matrix.numbers[12], 1);
  EXPECT_EQ(matrix.numbers[16], 3);
  // Unknown names are the scene builder's to reject.
  EXPECT_EQ(single_call("Basis \"squiggle\" 1 \"squiggle\" 1").strings[0], "squiggle");
}

TEST(RibParserRequests, GeometryFixedArguments) {
  const RecordedCall curves = single_call(
      "Curves \"cubic\" [4 7] \"nonperiodic\" \"P\" [0 0 0 1 1 1 2 2 2 3 3 3 "
      "0 0 0 1 1 1 2 2 2 3 3 3 4 4 4 5 5 5 6 6 6] \"constantwidth\" 0.5");
  EXPECT_EQ(curves.strings, (Strings{"cubic", "nonperiodic"}));
  EXPECT_EQ(curves.numbers, (Numbers{4, 7}));
  ASSERT_EQ(curves.params.params.size(), 2u);
  EXPECT_EQ(curves.params.params[0].element_count(), 11u);
  EXPECT_EQ(curves.params.get_float("constantwidth", 0), 0.5f);
  EXPECT_EQ(single_call("Sphere 1 -1 1 360").numbers, (Numbers{1, -1, 1, 360}));
  EXPECT_EQ(single_call("GeneralPolygon [4 3] \"P\" [0 0 0 1 0 0 1 1 0 0 1 0 .2 .2 0 .5 .2 0 .2 .5 0]").numbers,
            (Numbers{4, 3}));
  EXPECT_EQ(single_call("PointsPolygons [3] [0 1 2] \"P\" [0 0 0 1 0 0 0 1 0]").numbers, (Numbers{3, -1, 0, 1, 2}));
  EXPECT_EQ(single_call("PointsGeneralPolygons [1] [3] [0 1 2] \"P\" [0 0 0 1 0 0 0 1 0]").numbers,
            (Numbers{1, -1, 3, -1, 0, 1, 2}));
}

TEST(RibParserRequests, BareScalarAndBareStringParameterValues) {
  const RecordedCall display = single_call("Display \"a.tif\" \"file\" \"rgb\" \"string compression\" \"lzw\"");
  EXPECT_EQ(display.strings, (Strings{"a.tif", "file", "rgb"}));
  EXPECT_EQ(display.params.get_string("compression", ""), "lzw");
  EXPECT_EQ(display.params.find("compression")->decl, *parse_param_decl("uniform string"));
  const RecordedCall proj = single_call("Projection \"perspective\" \"fov\" 20.0");
  EXPECT_EQ(proj.params.get_float("fov", 0), 20.0f);
  const RecordedCall bracketed = single_call("Display \"a.tif\" \"file\" \"rgb\" \"string compression\" [\"lzw\"]");
  EXPECT_TRUE(bracketed.same_as(display));
}

TEST(RibParserRequests, InlineDeclarationsOverrideTheStandardTable) {
  const RecordedCall light = single_call(
      "LightSource \"pointlight\" 1 \"constant float intensity\" [3000] \"constant color lightcolor\" [1 1 1]");
  EXPECT_EQ(light.params.find("intensity")->decl, *parse_param_decl("constant float"));
  EXPECT_EQ(light.params.find("lightcolor")->element_count(), 1u);
  const RecordedCall curves = single_call(
      "Curves \"linear\" [2] \"nonperiodic\" \"vertex point P\" [0 0 0 1 1 1] "
      "\"uniform float constantwidth\" [0.8]");
  EXPECT_EQ(curves.params.find("P")->decl, *parse_param_decl("vertex point"));
  EXPECT_EQ(curves.params.find("constantwidth")->decl, *parse_param_decl("uniform float"));
}

TEST(RibParserRequests, StandardTableTypesUndeclaredNames) {
  const RecordedCall c = single_call(
      "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 0 1 1 1] \"width\" [.1 .2] "
      "\"Cs\" [1 0 0 0 1 0] \"st\" [0 0 1 1]");
  EXPECT_EQ(c.params.find("width")->decl, *parse_param_decl("varying float"));
  EXPECT_EQ(c.params.find("Cs")->decl, *parse_param_decl("varying color"));
  EXPECT_EQ(c.params.find("st")->element_count(), 2u);
  const RecordedCall s = single_call("Surface \"plastic\" \"Ka\" 1 \"specularcolor\" [1 1 1] \"texturename\" \"t.tx\"");
  EXPECT_EQ(s.params.find("specularcolor")->decl, *parse_param_decl("uniform color"));
  EXPECT_EQ(s.params.get_string("texturename", ""), "t.tx");
}

TEST(RibParserRequests, DeclareRecordsGlobalDeclarations) {
  auto r = parse_rib(
      "Declare \"MyP\" \" varying point[5]\"\nAttributeBegin\nDeclare \"facecol\" \"uniform color\"\nAttributeEnd\n"
      "Surface \"s\" \"MyP\" [0 0 0 1 1 1 2 2 2 3 3 3 4 4 4] \"facecol\" [1 0 0]");
  EXPECT_TRUE(r->ok);
  EXPECT_TRUE(r->diag.all().empty());
  const auto declares = r->target.named("Declare");
  ASSERT_EQ(declares.size(), 2u);
  EXPECT_EQ(declares[0].strings, (Strings{"MyP", "varying point[5]"}));
  const RecordedCall s = r->target.named("Surface").at(0);
  EXPECT_EQ(s.params.find("MyP")->decl, *parse_param_decl("varying point[5]"));
  EXPECT_EQ(s.params.find("MyP")->element_count(), 1u);
  // Declarations are not scoped by blocks.
  EXPECT_EQ(s.params.find("facecol")->decl, *parse_param_decl("uniform color"));
}

TEST(RibParserRequests, UndeclaredParametersAreInferredAndWarnedOnce) {
  auto r = parse_rib("Surface \"s\" \"foo\" [1 2 3] \"name\" \"x\"\nSurface \"t\" \"foo\" [4 5 6]");
  EXPECT_TRUE(r->ok);
  const RecordedCall first = r->target.named("Surface").at(0);
  EXPECT_EQ(first.params.find("foo")->decl, *parse_param_decl("uniform float[3]"));
  EXPECT_EQ(first.params.find("name")->decl, *parse_param_decl("uniform string"));
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 2u);  // "foo" once, "name" once
  EXPECT_NE(warnings[0].message.find("\"foo\""), std::string::npos);
  EXPECT_EQ(warnings[0].loc.line, 1);
  EXPECT_EQ(warnings[0].loc.column, 13);
}

TEST(RibParserRequests, VendorRequestsInferSilently) {
  auto r = parse_rib(
      "Option \"limits\" \"bucketsize\" [16 16] \"eyesplits\" [10]\nAttribute \"identifier\" \"name\" [\"x\"]\n"
      "Hider \"hidden\" \"jitter\" [1] \"depthfilter\" \"midpoint\"\nDisplay \"a\" \"file\" \"rgb\" \"quality\" 5");
  EXPECT_TRUE(r->ok);
  EXPECT_TRUE(r->diag.all().empty());
  EXPECT_EQ(r->target.calls.at(0).params.find("bucketsize")->decl, *parse_param_decl("uniform float[2]"));
}

TEST(RibParserRequests, IgnoredRequestsPassTheirArguments) {
  const auto calls = clean_calls(
      "Shutter 0 1\nShadingRate 1\nShadingInterpolation \"constant\"\nMatte 0\nBound [0 1 0 1 0 1]\n"
      "MotionBegin [0 1]\nMotionEnd\nSkew 45 0 1 0 1 0 0\nAtmosphere \"fog\" \"distance\" 5\n"
      "MakeTexture \"a.tif\" \"a.tx\" \"periodic\" \"clamp\" \"gaussian\" 2 2 \"float bias\" 0.5\nDepthOfField 22 45 "
      "1200");
  ASSERT_EQ(calls.size(), 11u);
  EXPECT_EQ(calls[0].request, "Shutter");
  EXPECT_EQ(calls[0].numbers, (Numbers{0, 1}));
  EXPECT_EQ(calls[2].strings, Strings{"constant"});
  EXPECT_EQ(calls[4].numbers.size(), 6u);
  EXPECT_EQ(calls[7].numbers.size(), 7u);
  EXPECT_EQ(calls[8].strings, Strings{"fog"});  // its parameter list is checked and dropped
  EXPECT_TRUE(calls[8].numbers.empty());
  EXPECT_EQ(calls[9].strings.size(), 5u);
  EXPECT_EQ(calls[9].numbers, (Numbers{2, 2}));
}

TEST(RibParserRequests, StructureCommentsAndCrlfAreWhitespace) {
  const auto calls = clean_calls("##RenderMan RIB-Structure 1.0\r\nversion 3.03\r\n# c\r\nWorldBegin\r\nWorldEnd\r\n");
  ASSERT_EQ(calls.size(), 3u);
  EXPECT_EQ(calls[2].loc.line, 5);
}

}  // namespace
}  // namespace darc::test
