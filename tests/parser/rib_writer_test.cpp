// RibWriter: canonical output, and the round trip parse -> write A -> parse A -> write B with
// A == B and the same calls both times.
#include "parser/rib_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "recording_target.h"

namespace darc::test {
namespace {

namespace fs = std::filesystem;

struct Written {
  std::string text;
  RecordingTarget calls;
  int errors = 0;
};

// Parses `text` (or the file `path`) into both a writer and a recording target.
Written write_and_record(const std::string& text, const std::string& path = "") {
  Written w;
  std::ostringstream out;
  RibWriter writer(out);
  Diagnostics diag([](const Diagnostic&) {});
  RibParser to_writer(writer, diag);
  RibParser to_recorder(w.calls, diag);
  if (path.empty()) {
    to_writer.parse_string(text, "a.rib");
    to_recorder.parse_string(text, "a.rib");
  } else {
    to_writer.parse_file(path);
    to_recorder.parse_file(path);
  }
  w.text = out.str();
  w.errors = diag.error_count();
  return w;
}

void expect_round_trip(const std::string& text, const std::string& path = "") {
  const Written a = write_and_record(text, path);
  EXPECT_EQ(a.errors, 0);
  const Written b = write_and_record(a.text);
  EXPECT_EQ(b.errors, 0) << a.text;
  EXPECT_EQ(a.text, b.text);
  ASSERT_EQ(a.calls.calls.size(), b.calls.calls.size());
  for (size_t i = 0; i < a.calls.calls.size(); ++i) {
    EXPECT_TRUE(a.calls.calls[i].same_as(b.calls.calls[i])) << "call " << i << ": " << a.calls.calls[i].request;
  }
}

TEST(RibWriter, CanonicalFormWithIndentationAndInlineDeclarations) {
  const Written w = write_and_record(
      "FrameBegin 1\nWorldBegin\nAttributeBegin\nColor 1 0 .5\n"
      "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 0 0 1 1 1] \"constantwidth\" 0.1\n"
      "AttributeEnd\nWorldEnd\nFrameEnd\n");
  EXPECT_EQ(w.text,
            "FrameBegin 1\n"
            "  WorldBegin\n"
            "    AttributeBegin\n"
            "      Color [1 0 0.5]\n"
            "      Curves \"linear\" [2] \"nonperiodic\" \"vertex point P\" [0 0 0 1 1 1] \"constant float "
            "constantwidth\" [0.1]\n"
            "    AttributeEnd\n"
            "  WorldEnd\n"
            "FrameEnd\n");
}

TEST(RibWriter, NumbersAreShortestRoundTrip) {
  EXPECT_EQ(rib_number(0.1), "0.1");
  EXPECT_EQ(rib_number(0.1f), "0.1");
  EXPECT_EQ(rib_number(3.04999995), "3.04999995");
  EXPECT_EQ(rib_number(-1.99124e-15), "-1.99124e-15");
  EXPECT_EQ(rib_number(320.0), "320");
  EXPECT_EQ(rib_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\n\"");
}

TEST(RibWriter, RoundTripOfEveryRequestForm) {
  expect_round_trip(
      "version 3.03\nDeclare \"MyP\" \" varying point[2]\"\nOption \"searchpath\" \"shader\" [\"../shaders:&\"]\n"
      "Format 320 240 1\nFrameAspectRatio 1.3333\nScreenWindow [-1 1 -.75 .75]\nCropWindow 0 1 0 1\n"
      "Projection \"perspective\" \"fov\" 30\nClipping 0.1 1000\nPixelSamples 4 4\nPixelFilter \"box\" 1 1\n"
      "Exposure 1 2.2\nQuantize \"rgba\" 255 0 255 0.5\nDisplay \"out.tif\" \"file\" \"rgba\" \"string compression\" "
      "\"lzw\"\nHider \"hidden\" \"jitter\" [1]\nShutter 0 1\nShadingInterpolation \"smooth\"\n"
      "MakeTexture \"a.tif\" \"a.tx\" \"periodic\" \"clamp\" \"gaussian\" 2 2\n"
      "FrameBegin 3\nIdentity\nTransform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 5 1]\nWorldBegin\n"
      "LightSource \"distantlight\" 1 \"from\" [0 0 0] \"to\" [0 0 1]\nLightSource \"spotlight\" \"key\"\n"
      "AreaLightSource \"arealight\" 7\nIlluminate 1 0\nAttributeBegin\nAttribute \"identifier\" \"name\" [\"hair\"]\n"
      "Orientation \"rh\"\nReverseOrientation\nSides 1\nColor [.2 .3 .4]\nOpacity 1 1 1\n"
      "Surface \"plastic\" \"Ka\" 1 \"specularcolor\" [1 1 1]\nDisplacement \"null\"\n"
      "Basis [-1 3 -3 1 3 -6 3 0 -3 3 0 0 1 0 0 0] 3 \"b-spline\" 1\nTransformBegin\nTranslate 1 2 3\n"
      "Rotate 90 0 1 0\nScale 2 2 2\nConcatTransform [2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1]\nPerspective 40\n"
      "CoordinateSystem \"a\"\nCoordSysTransform \"a\"\nTransformEnd\n"
      "Curves \"cubic\" [4] \"periodic\" \"P\" [0 0 0 1 1 1 2 2 2 3 3 3] \"MyP\" [1 2 3 4 5 6 7 8 9 10 11 12] "
      "\"width\" [.1 .2 .3 .4] \"string name\" \"x\\\\y\"\nSphere 1 -1 1 360\nPolygon \"P\" [0 0 0 1 0 0 0 1 0]\n"
      "GeneralPolygon [3] \"P\" [0 0 0 1 0 0 0 1 0]\nPointsPolygons [3] [0 1 2] \"P\" [0 0 0 1 0 0 0 1 0]\n"
      "PointsGeneralPolygons [1] [3] [0 1 2] \"P\" [0 0 0 1 0 0 0 1 0] \"facevarying float s\" [0 1 0]\n"
      "AttributeEnd\nObjectBegin 2\nSphere 1 -1 1 360\nObjectEnd\nObjectInstance 2\nWorldEnd\nFrameEnd\n");
}

// Every request of RiTarget::primitive, with its typed arguments (SubdivisionMesh with and
// without its optional tag arrays).
TEST(RibWriter, RoundTripOfThePrimitiveRequests) {
  const std::string P4 = "\"P\" [0 0 0 1 0 0 0 1 0 1 1 0]";
  expect_round_trip(
      "WorldBegin\nCone 2 0.5 270\nCylinder 1 -1 1 360\nDisk 0 1 360\nHyperboloid 1 0 0 0 1 1 360\n"
      "Paraboloid 1 0 1 360\nTorus 1 0.25 0 360 180\nPatch \"bilinear\" " + P4 +
      "\nPatchMesh \"bilinear\" 2 \"nonperiodic\" 2 \"nonperiodic\" " + P4 +
      "\nNuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"Pw\" [0 0 0 1 1 0 0 1 0 1 0 1 1 1 0 1]\n"
      "SubdivisionMesh \"catmull-clark\" [4] [0 1 3 2] " + P4 +
      "\nSubdivisionMesh \"catmull-clark\" [4] [0 1 3 2] [\"crease\" \"interpolateboundary\"] [2 1 0 0] [0 1] "
      "[2.5] " + P4 + "\nPoints \"P\" [0 0 0 1 1 1] \"constantwidth\" 0.1\nWorldEnd\n");
}

// The spellings the scene builder reads for ray tracing: typed, untyped and predeclared.
TEST(RibWriter, RoundTripOfTheRayTracingAttributesAndOptions) {
  expect_round_trip(
      "Option \"trace\" \"int maxdepth\" [3] \"bias\" 0.01\nWorldBegin\n"
      "LightSource \"spotlight\" 1 \"shadowname\" [\"raytrace\"]\n"
      "Attribute \"light\" \"string shadows\" [\"on\"]\nAttribute \"light\" \"shadows\" \"off\"\n"
      "Attribute \"visibility\" \"int transmission\" [1] \"string transmission\" [\"shader\"]\n"
      "Attribute \"visibility\" \"transmission\" 0\nAttribute \"render\" \"string casts_shadows\" [\"shade\"]\n"
      "WorldEnd\n");
  EXPECT_EQ(write_and_record("Option \"trace\" \"int maxdepth\" [3]\n").text,
            "Option \"trace\" \"uniform int maxdepth\" [3]\n");
}

TEST(RibWriter, RoundTripOfTheSharedRibs) {
  const fs::path dir = DARC_SHARED_RIBS_DIR "/aqsis";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "shared RIBs not found in " << dir;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".rib") continue;
    SCOPED_TRACE(entry.path().string());
    expect_round_trip("", entry.path().string());
    ++files;
  }
  EXPECT_GT(files, 0);
}

}  // namespace
}  // namespace darc::test
