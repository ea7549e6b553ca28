// A test RiTarget that records every call with its arguments flattened into numbers and
// strings, so tests can look at what the parser delivered and compare two parses.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/ri_target.h"
#include "parser/rib_parser.h"

namespace darc::test {

struct RecordedCall {
  std::string request;
  std::vector<double> numbers;
  std::vector<std::string> strings;
  ParamList params;
  SourceLoc loc;

  // Same call and arguments (positions are not compared).
  bool same_as(const RecordedCall& o) const {
    if (request != o.request || numbers != o.numbers || strings != o.strings) return false;
    if (params.params.size() != o.params.params.size()) return false;
    for (size_t i = 0; i < params.params.size(); ++i) {
      const Param& a = params.params[i];
      const Param& b = o.params.params[i];
      if (a.name != b.name || !(a.decl == b.decl) || a.floats != b.floats || a.strings != b.strings) return false;
    }
    return true;
  }
};

class RecordingTarget : public RiTarget {
 public:
  std::vector<RecordedCall> calls;

  // The calls named `request`, in order.
  std::vector<RecordedCall> named(const std::string& request) const {
    std::vector<RecordedCall> out;
    for (const RecordedCall& c : calls) {
      if (c.request == request) out.push_back(c);
    }
    return out;
  }

  // Every request of parser/ri_requests.def but the special ones: its arguments flattened by
  // kind in order (numbers to `numbers`, strings and handles to `strings`, a Basis as its name
  // and its 16 numbers, -1 between consecutive integer arrays).
#define DARC_RI_ON_ARG(Kind, name, what) flatten(call, Kind{}, name);
#define DARC_RI_REQUEST(Rib, method, reading, shape, args)                         \
  DARC_RI_IF_GENERIC_##reading(void method(DARC_RI_PARAMS(args) const SourceLoc& loc) override { \
    RecordedCall call{#Rib, {}, {}, {}, loc};                                      \
    int_arrays_in_call_ = 0;                                                       \
    DARC_RI_EACH(args)                                                             \
    calls.push_back(std::move(call));                                              \
  })
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args)                                         \
  DARC_RI_IF_GENERIC_##reading(                                                                       \
      void method(DARC_RI_PARAMS(args) const ParamList& params, const SourceLoc& loc) override { \
        RecordedCall call{#Rib, {}, {}, params, loc};                                                 \
        int_arrays_in_call_ = 0;                                                                      \
        DARC_RI_EACH(args)                                                                            \
        calls.push_back(std::move(call));                                                             \
      })
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL
#undef DARC_RI_ON_ARG

  void ignored_request(const std::string& r, const std::vector<double>& n, const std::vector<std::string>& s,
                       const SourceLoc& loc) override {
    calls.push_back({r, n, s, {}, loc});
  }
  // Numbers, then every array's values in order; strings, then every string array's.
  void primitive(const PrimitiveRequest& r, const ParamList& p, const SourceLoc& loc) override {
    std::vector<double> n = r.numbers;
    for (const auto& a : r.integer_arrays) n.insert(n.end(), a.begin(), a.end());
    for (const auto& a : r.number_arrays) n.insert(n.end(), a.begin(), a.end());
    std::vector<std::string> s = r.strings;
    for (const auto& a : r.string_arrays) s.insert(s.end(), a.begin(), a.end());
    calls.push_back({r.name, n, s, p, loc});
  }
  // Kept apart from `calls`: they are not requests the target models.
  std::vector<std::string> skipped_primitives;
  void skipped_primitive(const std::string& r, const SourceLoc&) override { skipped_primitives.push_back(r); }

 private:
  static void flatten(RecordedCall& c, RiInt, int v) { c.numbers.push_back(v); }
  static void flatten(RecordedCall& c, RiFloat, double v) { c.numbers.push_back(v); }
  template <int N>
  static void flatten(RecordedCall& c, RiNumbers<N>, double v) { c.numbers.push_back(v); }
  static void flatten(RecordedCall& c, RiNumbersNext, double v) { c.numbers.push_back(v); }
  static void flatten(RecordedCall& c, RiBool, bool v) { c.numbers.push_back(v ? 1.0 : 0.0); }
  static void flatten(RecordedCall& c, RiString, const std::string& v) { c.strings.push_back(v); }
  static void flatten(RecordedCall& c, RiHandle, const std::string& v) { c.strings.push_back(v); }
  static void flatten(RecordedCall& c, RiMatrix, const std::array<double, 16>& v) {
    c.numbers.insert(c.numbers.end(), v.begin(), v.end());
  }
  static void flatten(RecordedCall& c, RiColor, const std::array<float, 3>& v) {
    c.numbers.insert(c.numbers.end(), v.begin(), v.end());
  }
  static void flatten(RecordedCall& c, RiBasis, const BasisArg& v) {
    c.strings.push_back(v.name);
    c.numbers.insert(c.numbers.end(), v.matrix.begin(), v.matrix.end());
  }
  static void flatten(RecordedCall& c, RiFloatArray, const std::vector<double>& v) {
    c.numbers.insert(c.numbers.end(), v.begin(), v.end());
  }
  void flatten(RecordedCall& c, RiIntArray, const std::vector<int>& v) {
    if (int_arrays_in_call_++ > 0) c.numbers.push_back(-1);  // separator
    c.numbers.insert(c.numbers.end(), v.begin(), v.end());
  }
  int int_arrays_in_call_ = 0;  // of the call being recorded
};

// The outcome of parsing a text with a RecordingTarget and silent Diagnostics.
struct ParseResult {
  RecordingTarget target;
  Diagnostics diag{[](const Diagnostic&) {}};
  bool ok = false;

  std::vector<Diagnostic> errors() const { return of(Severity::Error); }
  std::vector<Diagnostic> warnings() const { return of(Severity::Warning); }

 private:
  std::vector<Diagnostic> of(Severity s) const {
    std::vector<Diagnostic> out;
    for (const Diagnostic& d : diag.all()) {
      if (d.severity == s) out.push_back(d);
    }
    return out;
  }
};

inline std::unique_ptr<ParseResult> parse_rib(const std::string& text, const std::string& name = "test.rib") {
  auto result = std::make_unique<ParseResult>();
  RibParser parser(result->target, result->diag);
  result->ok = parser.parse_string(text, name);
  return result;
}

}  // namespace darc::test
