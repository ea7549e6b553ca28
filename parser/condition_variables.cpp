#include "parser/condition_variables.h"

namespace darc {

namespace {

constexpr std::string_view kOptionPrefix = "Option:";
constexpr std::string_view kAttributePrefix = "Attribute:";

VariableValue find(const std::map<std::string, VariableValue, std::less<>>& values, std::string_view name) {
  const auto it = values.find(name);
  return it == values.end() ? VariableValue{} : it->second;
}

VariableValue value_of(const Param& p) {
  VariableValue v;
  const size_t count = p.strings.size() + p.floats.size();
  if (count == 0) return v;
  if (count > 1) {
    v.state = VariableValue::State::Array;
    v.array_size = count;
    return v;
  }
  v.state = VariableValue::State::Scalar;
  if (!p.strings.empty()) {
    v.value = p.strings[0];
  } else {
    v.value = double(p.floats[0]);
  }
  return v;
}

}  // namespace

void ConditionVariables::frame_begin(int number) {
  open(Scope::Frame);
  frame_ = number;
}

void ConditionVariables::frame_end() { close(Scope::Frame); }

void ConditionVariables::world_end() {
  // WorldEnd closes the attribute blocks left open inside it (SceneBuilder reports them).
  while (!saved_.empty() && saved_.back().scope == Scope::Attribute) close(Scope::Attribute);
  close(Scope::World);
}

void ConditionVariables::open(Scope scope) {
  Saved s{scope, attributes_, {}, frame_};
  if (scope == Scope::Frame) s.options = options_;
  saved_.push_back(std::move(s));
}

void ConditionVariables::close(Scope scope) {
  if (saved_.empty() || saved_.back().scope != scope) return;
  Saved& s = saved_.back();
  attributes_ = std::move(s.attributes);
  if (scope == Scope::Frame) {
    options_ = std::move(s.options);
    frame_ = s.frame;
  }
  saved_.pop_back();
}

void ConditionVariables::set(Values& values, const std::string& category, const ParamList& params) {
  for (const Param& p : params.params) values[category + ":" + p.name] = value_of(p);
}

void ConditionVariables::option(const std::string& category, const ParamList& params) {
  set(options_, category, params);
}

void ConditionVariables::attribute(const std::string& category, const ParamList& params) {
  set(attributes_, category, params);
}

VariableValue ConditionVariables::lookup(std::string_view name) const {
  if (name == "Frame") {
    VariableValue v;
    if (frame_) {
      v.state = VariableValue::State::Scalar;
      v.value = double(*frame_);
    }
    return v;
  }
  if (name.starts_with(kOptionPrefix)) return find(options_, name.substr(kOptionPrefix.size()));
  if (name.starts_with(kAttributePrefix)) return find(attributes_, name.substr(kAttributePrefix.size()));
  const VariableValue attribute = find(attributes_, name);
  return attribute.state != VariableValue::State::Undefined ? attribute : find(options_, name);
}

}  // namespace darc
