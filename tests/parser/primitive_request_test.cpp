// The geometry requests that reach RiTarget::primitive: each fixed argument lands in the typed
// list and position its signature says (parser/primitive_signatures.h), numbers may be
// bracketed, SubdivisionMesh's tag arrays are optional, and wrong arguments are located errors.
#include "parser/primitive_signatures.h"

#include <gtest/gtest.h>

#include "recording_target.h"

namespace darc::test {
namespace {

struct PrimitiveTarget : RecordingTarget {
  std::vector<PrimitiveRequest> requests;
  void primitive(const PrimitiveRequest& r, const ParamList& p, const SourceLoc& loc) override {
    requests.push_back(r);
    RecordingTarget::primitive(r, p, loc);
  }
};

PrimitiveRequest parse_one(const std::string& rib, int* errors = nullptr) {
  PrimitiveTarget target;
  Diagnostics diag([](const Diagnostic&) {});
  RibParser parser(target, diag);
  parser.parse_string("WorldBegin\n" + rib + "\nWorldEnd\n", "p.rib");
  if (errors) *errors = diag.error_count();
  return target.requests.empty() ? PrimitiveRequest{} : target.requests[0];
}

TEST(PrimitiveRequest, QuadricNumbersInOrderBareOrBracketed) {
  const PrimitiveRequest cone = parse_one("Cone 2 0.5 270");
  EXPECT_EQ(cone.name, "Cone");
  EXPECT_EQ(cone.numbers, (std::vector<double>{2, 0.5, 270}));
  EXPECT_EQ(parse_one("Hyperboloid [1 0 0 0 1 1 360]").numbers, (std::vector<double>{1, 0, 0, 0, 1, 1, 360}));
  EXPECT_EQ(parse_one("Torus 1 .25 0 360 180").numbers, (std::vector<double>{1, 0.25, 0, 360, 180}));
  EXPECT_EQ(parse_one("Sphere [1 -1 1 360]").numbers, parse_one("Sphere 1 -1 1 360").numbers);
}

TEST(PrimitiveRequest, PatchMeshStringsAndIntegers) {
  const PrimitiveRequest r =
      parse_one("PatchMesh \"bicubic\" 7 \"periodic\" 4 \"nonperiodic\" \"P\" [" + std::string(28 * 3 * 2, ' ') + "]");
  EXPECT_EQ(r.strings, (std::vector<std::string>{"bicubic", "periodic", "nonperiodic"}));
  EXPECT_EQ(r.numbers, (std::vector<double>{7, 4}));
}

TEST(PrimitiveRequest, NuPatchKnotArrays) {
  const PrimitiveRequest r = parse_one(
      "NuPatch 2 2 [0 0 1 1] 0 1 3 3 [0 0 0 1 1 1] 0 1 \"Pw\" [0 0 0 1 1 0 0 1 0 1 0 1 1 1 0 1 0 2 0 1 1 2 0 1]");
  EXPECT_EQ(r.numbers, (std::vector<double>{2, 2, 0, 1, 3, 3, 0, 1}));
  ASSERT_EQ(r.number_arrays.size(), 2u);
  EXPECT_EQ(r.number_arrays[0], (std::vector<double>{0, 0, 1, 1}));
  EXPECT_EQ(r.number_arrays[1], (std::vector<double>{0, 0, 0, 1, 1, 1}));
}

TEST(PrimitiveRequest, SubdivisionMeshTagsAreOptional) {
  const PrimitiveRequest bare =
      parse_one("SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] \"P\" [0 0 0 1 0 0 1 1 0 0 1 0]");
  EXPECT_EQ(bare.strings, (std::vector<std::string>{"catmull-clark"}));
  EXPECT_EQ(bare.integer_arrays, (std::vector<std::vector<int>>{{4}, {0, 1, 2, 3}}));
  EXPECT_TRUE(bare.string_arrays.empty());

  const PrimitiveRequest tagged = parse_one(
      "SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [\"crease\" \"interpolateboundary\"] [2 1 0 0] [0 1] [2.5] "
      "\"P\" [0 0 0 1 0 0 1 1 0 0 1 0]");
  EXPECT_EQ(tagged.string_arrays, (std::vector<std::vector<std::string>>{{"crease", "interpolateboundary"}}));
  ASSERT_EQ(tagged.integer_arrays.size(), 4u);
  EXPECT_EQ(tagged.integer_arrays[2], (std::vector<int>{2, 1, 0, 0}));
  EXPECT_EQ(tagged.integer_arrays[3], (std::vector<int>{0, 1}));
  EXPECT_EQ(tagged.number_arrays, (std::vector<std::vector<double>>{{2.5}}));
}

TEST(PrimitiveRequest, PointsHasOnlyAParameterList) {
  const PrimitiveRequest r = parse_one("Points \"P\" [0 0 0 1 1 1] \"constantwidth\" 0.1");
  EXPECT_EQ(r.name, "Points");
  EXPECT_TRUE(r.numbers.empty() && r.strings.empty() && r.integer_arrays.empty());
}

TEST(PrimitiveRequest, WrongArgumentsAreErrorsAtTheirPosition) {
  int errors = 0;
  PrimitiveTarget target;
  std::vector<Diagnostic> seen;
  Diagnostics diag([&](const Diagnostic& d) { seen.push_back(d); });
  RibParser parser(target, diag);
  parser.parse_string("WorldBegin\nCone 1 2 \"P\" [0 0 0]\nPatchMesh \"bilinear\" 2.5 \"nonperiodic\" 2 \"nonperiodic\"\n"
                      "Sphere 1 -1 1 360\nWorldEnd\n",
                      "p.rib");
  errors = diag.error_count();
  EXPECT_EQ(errors, 2);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_EQ(seen[0].loc.str(), "p.rib:2:10");
  EXPECT_NE(seen[0].message.find("3 numbers for height, radius and thetamax"), std::string::npos) << seen[0].message;
  EXPECT_NE(seen[1].message.find("nu"), std::string::npos) << seen[1].message;
  ASSERT_EQ(target.requests.size(), 1u) << "the parser resumes at the next request";
  EXPECT_EQ(target.requests[0].name, "Sphere");
}

TEST(PrimitiveRequest, EverySignatureIsFound) {
  for (const char* name : {"Sphere", "Cone", "Cylinder", "Disk", "Hyperboloid", "Paraboloid", "Torus", "Patch",
                           "PatchMesh", "NuPatch", "SubdivisionMesh", "Points"})
    EXPECT_NE(find_primitive_signature(name), nullptr) << name;
  EXPECT_EQ(find_primitive_signature("Curves"), nullptr) << "Curves has its own RiTarget method";
}

}  // namespace
}  // namespace darc::test
