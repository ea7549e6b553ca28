#include <gtest/gtest.h>

#include "parser/param_list.h"
#include "parser/standard_declarations.h"

namespace darc {
namespace {

TEST(ParamDecl, ParsesClassTypeAndArraySize) {
  const auto d = parse_param_decl("uniform float[3]");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->storage, StorageClass::Uniform);
  EXPECT_EQ(d->type, ParamType::Float);
  EXPECT_EQ(d->array_size, 3);
  EXPECT_EQ(d->components(), 3);
}

TEST(ParamDecl, ClassDefaultsToUniformAndLeadingSpaceIsTolerated) {
  const auto d = parse_param_decl(" varying point[5]");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->storage, StorageClass::Varying);
  EXPECT_EQ(d->type, ParamType::Point);
  EXPECT_EQ(d->components(), 15);
  const auto s = parse_param_decl("string");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->storage, StorageClass::Uniform);
  EXPECT_TRUE(s->is_string());
}

TEST(ParamDecl, ComponentsPerType) {
  EXPECT_EQ(parse_param_decl("vertex hpoint")->components(), 4);
  EXPECT_EQ(parse_param_decl("constant color")->components(), 3);
  EXPECT_EQ(parse_param_decl("matrix")->components(), 16);
  EXPECT_EQ(parse_param_decl("int")->type, ParamType::Integer);
  EXPECT_EQ(parse_param_decl("integer")->type, ParamType::Integer);
  EXPECT_EQ(parse_param_decl("facevarying normal")->storage, StorageClass::FaceVarying);
  EXPECT_EQ(parse_param_decl("facevertex vector")->storage, StorageClass::FaceVertex);
}

TEST(ParamDecl, RejectsInvalidDeclarations) {
  for (const char* bad : {"", "uniform", "floaty", "float[0]", "float[", "float[3", "float 3", "uniform uniform float",
                          "varying float[-2]", "float[99999999999]"}) {
    EXPECT_FALSE(parse_param_decl(bad)) << bad;
  }
}

TEST(ParamDecl, InlineDeclarationSplitsDeclAndName) {
  std::string name;
  auto d = parse_inline_decl("vertex point P", name);
  ASSERT_TRUE(d);
  EXPECT_EQ(name, "P");
  EXPECT_EQ(d->storage, StorageClass::Vertex);
  d = parse_inline_decl("uniform float constantwidth", name);
  ASSERT_TRUE(d);
  EXPECT_EQ(name, "constantwidth");
  EXPECT_EQ(d->storage, StorageClass::Uniform);
  d = parse_inline_decl("float[4] width", name);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->array_size, 4);
  EXPECT_EQ(name, "width");
}

TEST(ParamDecl, PlainTokensHaveNoInlineDeclaration) {
  std::string name;
  EXPECT_FALSE(parse_inline_decl("P", name));
  EXPECT_EQ(name, "P");
  EXPECT_FALSE(parse_inline_decl("  constantwidth ", name));
  EXPECT_EQ(name, "constantwidth");
  // A keyword prefix is not a keyword: "constantwidth" is not "constant width".
  EXPECT_FALSE(parse_inline_decl("floaty thing", name));
  EXPECT_EQ(name, "floaty thing");
}

TEST(ParamDecl, ToStringRoundTrips) {
  for (const char* text : {"varying float[2]", "vertex point", "constant color", "uniform string", "uniform int[3]",
                           "facevarying normal", "vertex hpoint", "uniform matrix"}) {
    const auto d = parse_param_decl(text);
    ASSERT_TRUE(d) << text;
    EXPECT_EQ(to_string(*d), text);
    EXPECT_EQ(parse_param_decl(to_string(*d)), d);
  }
}

TEST(StandardDeclarations, PrimitiveVariablesAndShaderParameters) {
  EXPECT_EQ(standard_declaration("P"), parse_param_decl("vertex point"));
  EXPECT_EQ(standard_declaration("Pw"), parse_param_decl("vertex hpoint"));
  EXPECT_EQ(standard_declaration("N"), parse_param_decl("varying normal"));
  EXPECT_EQ(standard_declaration("st"), parse_param_decl("varying float[2]"));
  EXPECT_EQ(standard_declaration("width"), parse_param_decl("varying float"));
  EXPECT_EQ(standard_declaration("constantwidth"), parse_param_decl("constant float"));
  EXPECT_EQ(standard_declaration("lightcolor"), parse_param_decl("uniform color"));
  EXPECT_EQ(standard_declaration("from"), parse_param_decl("uniform point"));
  EXPECT_EQ(standard_declaration("texturename"), parse_param_decl("uniform string"));
  EXPECT_EQ(standard_declaration("shadowname"), parse_param_decl("uniform string"));
  EXPECT_EQ(standard_declaration("roughness"), parse_param_decl("uniform float"));
  EXPECT_FALSE(standard_declaration("foo"));
}

TEST(ParamList, LookupsAndElementCount) {
  ParamList list;
  Param p;
  p.name = "P";
  p.decl = *standard_declaration("P");
  p.floats = {0, 0, 0, 1, 1, 1};
  list.params.push_back(p);
  Param s;
  s.name = "texturename";
  s.decl = *standard_declaration("texturename");
  s.strings = {"grass.tx"};
  list.params.push_back(s);
  EXPECT_EQ(list.find("P")->element_count(), 2u);
  EXPECT_EQ(list.find("missing"), nullptr);
  EXPECT_EQ(list.get_float("P", 7), 0.0f);
  EXPECT_EQ(list.get_float("Kd", 7), 7.0f);
  EXPECT_EQ(list.get_string("texturename", ""), "grass.tx");
  EXPECT_EQ(list.get_string("other", "x"), "x");
}

}  // namespace
}  // namespace darc
