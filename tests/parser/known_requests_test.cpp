// Request names: those of the RI Spec and RenderMan that darc does not implement are "not
// supported" (one warning per name, with its position), other names are "unknown".
#include "parser/known_requests.h"

#include <gtest/gtest.h>

#include <set>

#include "recording_target.h"

namespace darc::test {
namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(KnownRequests, RenderManRequestsAreNotSupportedNotUnknown) {
  auto r = parse_rib(R"RIB(LightFilter "PxrBlockerLightFilter" "b" "float density" [1]
SampleFilter "PxrBackgroundSampleFilter" "bg"
LightFilter "PxrRodLightFilter" "rod"
DisplayFilter "PxrBackgroundDisplayFilter" "bgd"
  Displace "PxrDisplace" "disp" "float dispAmount" [0.1]
DisplayChannel "color Ci"
System "ls"
Procedural2 "DynamicLoad" "SubdivisionMesh" "string dsoname" ["x"]
Resource "r" "attributes" "string operation" ["save"]
Frobnicate 1 2
WorldBegin
)RIB");
  EXPECT_TRUE(r->ok) << "a request darc does not support is a warning";
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 9u) << "one warning per request name";
  EXPECT_EQ(warnings[0].message, "request \"LightFilter\" (RenderMan 19+ RIB) is not supported: skipped");
  EXPECT_EQ(warnings[0].loc.str(), "test.rib:1:1");
  EXPECT_EQ(warnings[0].request, "LightFilter");
  EXPECT_EQ(warnings[3].request, "Displace");
  EXPECT_EQ(warnings[3].loc.str(), "test.rib:5:3");
  EXPECT_EQ(warnings[4].message, "request \"DisplayChannel\" (RI Spec 3.4 / PRMan) is not supported: skipped");
  EXPECT_EQ(warnings[8].message, "unknown request \"Frobnicate\": skipped");
  ASSERT_EQ(r->target.calls.size(), 1u) << "their arguments are skipped";
  EXPECT_EQ(r->target.calls[0].request, "WorldBegin");
}

TEST(KnownRequests, SkippedPrimitivesAreToldToTheTarget) {
  auto r = parse_rib(
      "WorldBegin\nBlobby 1 [1001 0] [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] [\"\"]\nDisplace \"PxrDisplace\" \"d\"\n"
      "Geometry \"teapot\"\nBlobby 1 [1001 0] [2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1] [\"\"]\nWorldEnd\n");
  EXPECT_EQ(r->target.skipped_primitives, (std::vector<std::string>{"Blobby", "Geometry", "Blobby"}))
      << "geometry only, and every call (the warning is once per name)";
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0].message, "request \"Blobby\" (RI Spec 3.2) is not supported: skipped");
}

TEST(KnownRequests, TrimCurveWarnsOnceThatTheSurfaceIsUntrimmed) {
  auto r = parse_rib(
      "WorldBegin\nTrimCurve [1] [2] [0 0 1 1] [0] [1] [2] [0 1] [0 1] [1 1]\n"
      "TrimCurve [1] [2] [0 0 1 1] [0] [1] [2] [0 1] [0 1] [1 1]\nWorldEnd\n");
  EXPECT_TRUE(r->ok);
  const auto warnings = r->warnings();
  ASSERT_EQ(warnings.size(), 1u) << "once per run";
  EXPECT_EQ(warnings[0].message, "trim curves are not supported: the untrimmed surface is rendered");
  EXPECT_EQ(warnings[0].loc.str(), "test.rib:2:1");
  EXPECT_TRUE(r->target.skipped_primitives.empty()) << "an attribute, not a primitive";
  ASSERT_EQ(r->target.calls.size(), 2u) << "its arguments are skipped";
  EXPECT_EQ(r->target.calls[1].request, "WorldEnd");
}

TEST(KnownRequests, NoKnownNameIsReportedUnknown) {
  for (const KnownRequest& known : known_requests()) {
    SCOPED_TRACE(std::string(known.name));
    auto r = parse_rib(std::string(known.name) + "\n");
    for (const Diagnostic& d : r->diag.all()) EXPECT_FALSE(contains(d.message, "unknown request")) << d.str();
  }
}

TEST(KnownRequests, TheTableHasEachNameOnce) {
  std::set<std::string_view> names;
  for (const KnownRequest& known : known_requests()) EXPECT_TRUE(names.insert(known.name).second) << known.name;
  EXPECT_GT(names.size(), 130u);
  EXPECT_FALSE(find_known_request("bxdf").has_value()) << "RIB request names are case-sensitive";
  EXPECT_EQ(find_known_request("Procedural2")->kind, RequestKind::Geometry);
}

}  // namespace
}  // namespace darc::test
