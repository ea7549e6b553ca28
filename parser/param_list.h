// Typed RI parameter lists: the "token" value-array pairs that follow a request's fixed
// arguments. The parser resolves each token's declaration (inline "vertex point P",
// Declare'd, or standard) so targets receive values with their storage class and type.
#pragma once

#include "parser/source_loc.h"

#include <optional>
#include <string>
#include <vector>

namespace darc {

enum class StorageClass { Constant, Uniform, Varying, Vertex, FaceVarying, FaceVertex };
// Struct: only as RenderMan 21+ writes it, "reference struct manifold" (a connection to a pattern's
// struct output, such as PxrManifold2D's "result").
enum class ParamType { Float, Integer, String, Color, Point, Vector, Normal, HPoint, Matrix, Struct };

struct ParamDecl {
  StorageClass storage = StorageClass::Uniform;
  ParamType type = ParamType::Float;
  int array_size = 1;  // "float[4]" -> 4
  // RenderMan 21+ "reference color diffuseColor" ["pattern:output"]: the value is a connection to
  // a Pattern's output, written as strings, instead of a value of the type.
  bool reference = false;

  // Numbers per element: 3 for point/vector/normal/color, 4 hpoint, 16 matrix, else 1;
  // times array_size.
  int components() const;
  bool is_string() const { return type == ParamType::String || reference; }
  bool operator==(const ParamDecl&) const = default;
};

// Parses a declaration such as "uniform float[3]", " varying point", "vertex hpoint",
// "constant color", "string", "int", "reference color". Returns nullopt when it is not a valid declaration.
std::optional<ParamDecl> parse_param_decl(const std::string& text);
// Splits an inline token "vertex point P" into its declaration and name. If the token has no
// inline declaration, returns nullopt and sets name to the trimmed token.
std::optional<ParamDecl> parse_inline_decl(const std::string& token, std::string& name);
std::string to_string(StorageClass c);
std::string to_string(ParamType t);
std::string to_string(const ParamDecl& d);  // "varying float[2]"

struct Param {
  std::string name;  // without any inline declaration
  ParamDecl decl;
  std::vector<float> floats;         // numeric values (integers too, as exact floats)
  std::vector<std::string> strings;  // for string parameters
  SourceLoc loc;                     // position of the token string

  // Number of elements (values / components).
  size_t element_count() const;
};

class ParamList {
 public:
  std::vector<Param> params;

  const Param* find(const std::string& name) const;
  // Convenience lookups with defaults (first value of the named parameter).
  float get_float(const std::string& name, float fallback) const;
  std::string get_string(const std::string& name, const std::string& fallback) const;
  bool empty() const { return params.empty(); }
};

}  // namespace darc
