// SceneBuilder and Attribute "Ri" "Basis" / "BasisStep", the RenderMan 21+ spelling of Basis:
// the same basis as the Basis request, so b-spline hair is read with b-spline vertex counts.
#include <gtest/gtest.h>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

std::vector<Diagnostic> errors(const Built& b) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error) out.push_back(d);
  return out;
}

// Five control points: two b-spline segments (step 1), but no whole number of Bézier ones.
const char* const kFivePointHair =
    "Curves \"cubic\" [5] \"nonperiodic\" \"P\" [0 0 0  0 1 0  1 2 0  1 3 0  0 4 0] \"constantwidth\" [0.1]\n";

Built hair_with(const std::string& basis_request) {
  return build("WorldBegin\n" + basis_request + "\n" + kFivePointHair + "WorldEnd\n");
}

void expect_same_curves(const Built& a, const Built& b) {
  ASSERT_EQ(a.scenes.size(), 1u);
  ASSERT_EQ(b.scenes.size(), 1u);
  const CurveSet& x = a.scenes[0].curves;
  const CurveSet& y = b.scenes[0].curves;
  ASSERT_EQ(x.size(), y.size());
  ASSERT_EQ(x.cp.size(), y.cp.size());
  for (size_t i = 0; i < x.cp.size(); ++i) {
    EXPECT_EQ(x.cp[i].x, y.cp[i].x) << i;
    EXPECT_EQ(x.cp[i].y, y.cp[i].y) << i;
    EXPECT_EQ(x.cp[i].z, y.cp[i].z) << i;
  }
}

TEST(SceneBuilderRiAttribute, BasisSetsTheBasisAsTheBasisRequestDoes) {
  const Built reference = hair_with("Basis \"b-spline\" 1 \"b-spline\" 1");
  ASSERT_TRUE(errors(reference).empty());
  ASSERT_EQ(reference.scenes[0].curves.size(), 2u);
  for (const char* spelling :
       {"Attribute \"Ri\" \"string Basis\" [\"b-spline\" \"b-spline\"] \"int BasisStep\" [1 1]",
        "Attribute \"Ri\" \"constant string[2] Basis\" [\"b-spline\" \"b-spline\"] \"constant int[2] BasisStep\" [1 1]",
        "Attribute \"Ri\" \"string Basis\" [\"b-spline\"]",
        "Attribute \"Ri\" \"string Basis\" [\"b-spline\"] \"int BasisStep\" [1]"}) {
    SCOPED_TRACE(spelling);
    const Built b = hair_with(spelling);
    EXPECT_TRUE(errors(b).empty()) << errors(b)[0].str();
    EXPECT_TRUE(b.diagnostics.empty()) << b.diagnostics[0].str();
    expect_same_curves(reference, b);
  }
}

TEST(SceneBuilderRiAttribute, WithoutItTheHairIsRejected) {
  // The bug this guards against: the attribute was ignored, the Bézier default applied.
  const Built b = hair_with("Attribute \"Ri\" \"string Basis\" [\"bezier\"]");
  ASSERT_EQ(errors(b).size(), 1u);
  EXPECT_EQ(errors(b)[0].request, "Curves");
}

TEST(SceneBuilderRiAttribute, AStepAloneChangesTheStepOfTheBasisInEffect) {
  const Built reference = hair_with("Basis \"catmull-rom\" 2 \"catmull-rom\" 1");
  const Built b = hair_with("Basis \"catmull-rom\" 2 \"catmull-rom\" 2\nAttribute \"Ri\" \"int BasisStep\" [2 1]");
  EXPECT_TRUE(errors(b).empty()) << errors(b)[0].str();
  expect_same_curves(reference, b);
}

TEST(SceneBuilderRiAttribute, BadValuesAreErrorsAndChangeNothing) {
  for (const char* bad : {"Attribute \"Ri\" \"string Basis\" [\"bspline\"]",
                          "Attribute \"Ri\" \"string Basis\" [\"b-spline\" \"b-spline\" \"b-spline\"]",
                          "Attribute \"Ri\" \"float Basis\" [1 2 3]",
                          "Attribute \"Ri\" \"string Basis\" [\"b-spline\"] \"int BasisStep\" [0]",
                          "Attribute \"Ri\" \"string Basis\" [\"b-spline\"] \"float BasisStep\" [1.5]"}) {
    SCOPED_TRACE(bad);
    const Built b = build(std::string("WorldBegin\nBasis \"b-spline\" 1 \"b-spline\" 1\n") + bad + "\n" +
                          kFivePointHair + "WorldEnd\n");
    ASSERT_EQ(errors(b).size(), 1u);
    EXPECT_EQ(errors(b)[0].request, "Attribute");
    EXPECT_EQ(b.scenes[0].curves.size(), 2u) << "the b-spline basis set before stays";
  }
}

TEST(SceneBuilderRiAttribute, OtherRiAttributesWarnOncePerName) {
  const Built b = build(
      "WorldBegin\nAttribute \"Ri\" \"float ShadingRate\" [1]\nAttribute \"Ri\" \"float ShadingRate\" [2]\n"
      "Sphere 1 -1 1 360\nWorldEnd\n");
  ASSERT_EQ(b.diagnostics.size(), 1u);
  EXPECT_EQ(b.diagnostics[0].severity, Severity::Warning);
  EXPECT_EQ(b.diagnostics[0].message, "Attribute \"Ri\" \"ShadingRate\" has no effect in darc: ignored");
}

}  // namespace
}  // namespace darc
