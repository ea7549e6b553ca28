// The RenderMan 21+ (RIS) shading requests: Bxdf, Light, Pattern and Integrator reach the target
// with their plugin name, handle and parameters, and "reference" parameters carry the pattern
// output they are connected to.
#include <gtest/gtest.h>

#include "recording_target.h"

namespace darc::test {
namespace {

using Strings = std::vector<std::string>;

TEST(RisRequests, EachRequestPassesItsNameHandleAndParameters) {
  auto r = parse_rib(R"RIB(Integrator "PxrPathTracer" "pt" "int maxPathLength" [4]
Pattern "PxrHairColor" "hc" "float melanin" [0.4]
Bxdf "PxrMarschnerHair" "hair" "reference color diffuseColor" ["hc:resultDiffuse"] "float diffuseGain" [0.5]
Light "PxrRectLight" "key" "float intensity" [4] "color lightColor" [1 0.5 0.25]
)RIB");
  EXPECT_TRUE(r->ok);
  EXPECT_TRUE(r->diag.all().empty()) << r->diag.all()[0].str();
  ASSERT_EQ(r->target.calls.size(), 4u);
  const auto& c = r->target.calls;
  EXPECT_EQ(c[0].request, "Integrator");
  EXPECT_EQ(c[0].strings, (Strings{"PxrPathTracer", "pt"}));
  EXPECT_EQ(c[1].request, "Pattern");
  EXPECT_EQ(c[1].strings, (Strings{"PxrHairColor", "hc"}));
  EXPECT_EQ(c[2].request, "Bxdf");
  EXPECT_EQ(c[2].strings, (Strings{"PxrMarschnerHair", "hair"}));
  EXPECT_EQ(c[3].request, "Light");
  EXPECT_EQ(c[3].strings, (Strings{"PxrRectLight", "key"}));
  ASSERT_EQ(c[3].params.params.size(), 2u);
  EXPECT_EQ(c[3].params.params[1].decl.type, ParamType::Color);
  EXPECT_EQ(c[3].params.params[1].floats, (std::vector<float>{1, 0.5f, 0.25f}));

  ASSERT_EQ(c[2].params.params.size(), 2u);
  const Param& connected = c[2].params.params[0];
  EXPECT_EQ(connected.name, "diffuseColor");
  EXPECT_TRUE(connected.decl.reference);
  EXPECT_EQ(connected.decl.type, ParamType::Color);
  EXPECT_TRUE(connected.decl.is_string()) << "a reference's value is the connection, a string";
  EXPECT_EQ(connected.strings, Strings{"hc:resultDiffuse"});
  EXPECT_FALSE(c[2].params.params[1].decl.reference);
}

TEST(RisRequests, AReferenceDeclarationParses) {
  std::string name;
  const auto d = parse_inline_decl("reference float diffuseGain", name);
  ASSERT_TRUE(d);
  EXPECT_EQ(name, "diffuseGain");
  EXPECT_TRUE(d->reference);
  EXPECT_EQ(d->type, ParamType::Float);
  EXPECT_EQ(to_string(*d), "reference uniform float");
  EXPECT_TRUE(parse_param_decl("reference uniform color")->reference);
  EXPECT_FALSE(parse_param_decl("color")->reference);
  EXPECT_FALSE(parse_inline_decl("referenceColor", name)) << "a plain name is not a declaration";
  EXPECT_EQ(name, "referenceColor");
}

TEST(RisRequests, AReferenceToAStructParses) {
  // PxrTexture's "reference struct manifold" ["m:result"], a connection to PxrManifold2D.
  auto r = parse_rib(R"RIB(Pattern "PxrTexture" "t" "reference struct manifold" ["m:result"]
)RIB");
  EXPECT_TRUE(r->diag.all().empty()) << r->diag.all()[0].str();
  ASSERT_EQ(r->target.calls.size(), 1u);
  ASSERT_EQ(r->target.calls[0].params.params.size(), 1u);
  const Param& p = r->target.calls[0].params.params[0];
  EXPECT_EQ(p.name, "manifold");
  EXPECT_TRUE(p.decl.reference);
  EXPECT_EQ(p.decl.type, ParamType::Struct);
  EXPECT_EQ(p.strings, Strings{"m:result"});
  EXPECT_EQ(to_string(p.decl), "reference uniform struct");
}

TEST(RisRequests, AReferenceWithNumbersIsAnError) {
  auto r = parse_rib("Bxdf \"PxrSurface\" \"s\" \"reference color diffuseColor\" [1 0 0]\nWorldBegin\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_NE(r->errors()[0].message.find("expected strings"), std::string::npos) << r->errors()[0].message;
  EXPECT_EQ(r->target.named("Bxdf").size(), 0u);
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u) << "the parser goes on at the next request";
}

TEST(RisRequests, AMissingHandleIsAnError) {
  auto r = parse_rib("Bxdf \"PxrSurface\"\nLight \"PxrDistantLight\"\nWorldBegin\n");
  EXPECT_EQ(r->errors().size(), 2u);
  EXPECT_EQ(r->target.named("WorldBegin").size(), 1u);
}

}  // namespace
}  // namespace darc::test
