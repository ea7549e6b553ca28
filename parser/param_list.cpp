#include "parser/param_list.h"

#include <fmt/format.h>

#include <boost/spirit/home/x3.hpp>

namespace darc {

namespace {

namespace x3 = boost::spirit::x3;

// Largest "[n]" accepted in a declaration; far above any real use, and keeps
// components() (n times up to 16) far from int overflow.
constexpr unsigned kMaxDeclArraySize = 1u << 20;

// Keyword tables of the declaration grammar. They are built once and never modified.
const x3::symbols<StorageClass>& storage_class_keywords() {
  static const x3::symbols<StorageClass> keywords({{"constant", StorageClass::Constant},
                                                   {"uniform", StorageClass::Uniform},
                                                   {"varying", StorageClass::Varying},
                                                   {"vertex", StorageClass::Vertex},
                                                   {"facevarying", StorageClass::FaceVarying},
                                                   {"facevertex", StorageClass::FaceVertex}});
  return keywords;
}

const x3::symbols<ParamType>& type_keywords() {
  static const x3::symbols<ParamType> keywords({{"float", ParamType::Float},
                                                {"int", ParamType::Integer},
                                                {"integer", ParamType::Integer},
                                                {"string", ParamType::String},
                                                {"color", ParamType::Color},
                                                {"point", ParamType::Point},
                                                {"vector", ParamType::Vector},
                                                {"normal", ParamType::Normal},
                                                {"hpoint", ParamType::HPoint},
                                                {"matrix", ParamType::Matrix},
                                                {"struct", ParamType::Struct}});
  return keywords;
}

// Parses "[class] type [ '[' n ']' ]" and, when `name` is given, a following name. The
// keywords must end at a word boundary so that "constantwidth" is a name, not "constant width".
bool parse_declaration(std::string_view text, ParamDecl& decl, std::string* name) {
  const auto word_end = !(x3::alnum | x3::char_('_'));
  const auto set_class = [&decl](auto& ctx) { decl.storage = x3::_attr(ctx); };
  const auto set_type = [&decl](auto& ctx) { decl.type = x3::_attr(ctx); };
  unsigned array_size = 1;
  const auto set_size = [&array_size](auto& ctx) { array_size = x3::_attr(ctx); };
  const auto set_reference = [&decl](auto&) { decl.reference = true; };
  const auto declaration = -x3::lexeme[x3::lit("reference")[set_reference] >> word_end] >>
                           -x3::lexeme[storage_class_keywords()[set_class] >> word_end] >>
                           x3::lexeme[type_keywords()[set_type] >> word_end] >>
                           -(x3::lit('[') >> x3::uint_[set_size] >> x3::lit(']'));
  decl = ParamDecl{};
  auto first = text.begin();
  bool ok = false;
  if (name) {
    const auto set_name = [name](auto& ctx) { *name = x3::_attr(ctx); };
    ok = x3::phrase_parse(first, text.end(), declaration >> x3::lexeme[(+x3::graph)[set_name]] >> x3::eoi, x3::space);
  } else {
    ok = x3::phrase_parse(first, text.end(), declaration >> x3::eoi, x3::space);
  }
  if (!ok || array_size == 0 || array_size > kMaxDeclArraySize) return false;
  decl.array_size = static_cast<int>(array_size);
  return true;
}

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

int type_components(ParamType t) {
  switch (t) {
    case ParamType::Color:
    case ParamType::Point:
    case ParamType::Vector:
    case ParamType::Normal:
      return 3;
    case ParamType::HPoint:
      return 4;
    case ParamType::Matrix:
      return 16;
    default:
      return 1;
  }
}

}  // namespace

int ParamDecl::components() const { return type_components(type) * array_size; }

std::optional<ParamDecl> parse_param_decl(const std::string& text) {
  ParamDecl decl;
  if (!parse_declaration(text, decl, nullptr)) return std::nullopt;
  return decl;
}

std::optional<ParamDecl> parse_inline_decl(const std::string& token, std::string& name) {
  const std::string_view trimmed = trim(token);
  // Fast path: a plain name ("P", "width") has no inner blank, so cannot carry a declaration.
  if (trimmed.find_first_of(" \t\n\r") == std::string_view::npos) {
    name.assign(trimmed);
    return std::nullopt;
  }
  ParamDecl decl;
  std::string parsed_name;
  if (!parse_declaration(trimmed, decl, &parsed_name)) {
    name.assign(trimmed);
    return std::nullopt;
  }
  name = std::move(parsed_name);
  return decl;
}

std::string to_string(StorageClass c) {
  switch (c) {
    case StorageClass::Constant:
      return "constant";
    case StorageClass::Uniform:
      return "uniform";
    case StorageClass::Varying:
      return "varying";
    case StorageClass::Vertex:
      return "vertex";
    case StorageClass::FaceVarying:
      return "facevarying";
    case StorageClass::FaceVertex:
      return "facevertex";
  }
  return "uniform";
}

std::string to_string(ParamType t) {
  switch (t) {
    case ParamType::Float:
      return "float";
    case ParamType::Integer:
      return "int";
    case ParamType::String:
      return "string";
    case ParamType::Color:
      return "color";
    case ParamType::Point:
      return "point";
    case ParamType::Vector:
      return "vector";
    case ParamType::Normal:
      return "normal";
    case ParamType::HPoint:
      return "hpoint";
    case ParamType::Matrix:
      return "matrix";
    case ParamType::Struct:
      return "struct";
  }
  return "float";
}

std::string to_string(const ParamDecl& d) {
  const char* reference = d.reference ? "reference " : "";
  if (d.array_size == 1) return fmt::format("{}{} {}", reference, to_string(d.storage), to_string(d.type));
  return fmt::format("{}{} {}[{}]", reference, to_string(d.storage), to_string(d.type), d.array_size);
}

size_t Param::element_count() const {
  if (decl.is_string()) return decl.array_size > 0 ? strings.size() / static_cast<size_t>(decl.array_size) : 0;
  const int n = decl.components();
  return n > 0 ? floats.size() / static_cast<size_t>(n) : 0;
}

const Param* ParamList::find(const std::string& name) const {
  for (const Param& p : params) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

float ParamList::get_float(const std::string& name, float fallback) const {
  const Param* p = find(name);
  return p && !p->floats.empty() ? p->floats.front() : fallback;
}

std::string ParamList::get_string(const std::string& name, const std::string& fallback) const {
  const Param* p = find(name);
  return p && !p->strings.empty() ? p->strings.front() : fallback;
}

}  // namespace darc
