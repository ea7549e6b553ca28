// The values a conditional RIB expression can refer to ($Frame, options, attributes), kept by
// the parser from the requests it reads: the frame number of FrameBegin, the parameters of
// Option and Attribute, scoped as RI scopes them (options by FrameBegin/FrameEnd; attributes
// by FrameBegin, WorldBegin and AttributeBegin blocks). This mirrors a small part of the
// graphics state on the parser's side because conditions decide which requests the target
// sees at all.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/condition_expression.h"
#include "parser/param_list.h"

namespace darc {

class ConditionVariables {
 public:
  // Call each after the target accepted the request (a rejected block request changes nothing).
  void frame_begin(int number);
  void frame_end();
  void world_begin() { open(Scope::World); }
  void world_end();
  void attribute_begin() { open(Scope::Attribute); }
  void attribute_end() { close(Scope::Attribute); }
  void option(const std::string& category, const ParamList& params);
  void attribute(const std::string& category, const ParamList& params);

  // "Frame"; "Option:category:name" and "Attribute:category:name"; "category:name" (the
  // attribute if set, else the option).
  VariableValue lookup(std::string_view name) const;

 private:
  enum class Scope { Frame, World, Attribute };
  // "category:name" -> value; single values only are kept whole (conditions compare scalars).
  using Values = std::map<std::string, VariableValue, std::less<>>;
  struct Saved {
    Scope scope;
    Values attributes;
    Values options;  // Frame only
    std::optional<int> frame;
  };

  void open(Scope scope);
  // Closes the innermost scope when it is `scope` (a mismatched end was the target's error).
  void close(Scope scope);
  static void set(Values& values, const std::string& category, const ParamList& params);

  std::optional<int> frame_;
  Values options_;
  Values attributes_;
  std::vector<Saved> saved_;
};

}  // namespace darc
