// The one list of RI requests (parser/ri_requests.def) against everything derived from it: for
// every request of the list, a call with sample arguments of each kind is written by RibWriter,
// parsed back (through the parser's table or its own handlers), written again, kept by
// CallRecorder and replayed. Each step must give the same text, so a request added to the list
// is read, written, recorded and replayed without anything else to write.
#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "parser/call_recorder.h"
#include "parser/diagnostics.h"
#include "parser/primitive_signatures.h"
#include "parser/request_table.h"
#include "parser/rib_parser.h"
#include "parser/rib_writer.h"
#include "parser/ri_target.h"

namespace darc {
namespace {

// A sample value of each kind, distinct from the kind's default so that a value lost on the way
// shows.
int sample(RiInt) { return 3; }
double sample(RiFloat) { return 0.25; }
bool sample(RiBool) { return true; }
std::string sample(RiString) { return "name \"quoted\""; }
std::string sample(RiHandle) { return "7"; }
std::array<double, 16> sample(RiMatrix) {
  std::array<double, 16> m{};
  for (size_t i = 0; i < m.size(); ++i) m[i] = 0.5 * double(i) - 1;
  return m;
}
std::array<float, 3> sample(RiColor) { return {0.1f, 0.2f, 0.3f}; }
BasisArg sample(RiBasis) { return {"catmull-rom", {}}; }
std::vector<int> sample(RiIntArray) { return {4, 5}; }
std::vector<double> sample(RiFloatArray) { return {0, 0.5}; }
template <int N>
double sample(RiNumbers<N>) {
  return 1.5;
}
double sample(RiNumbersNext) { return -2.0; }

ParamList sample_params() {
  ParamList list;
  Param p;
  p.name = "weight";
  p.decl.storage = StorageClass::Uniform;
  p.decl.type = ParamType::Float;
  p.floats = {0.75f};
  list.params.push_back(p);
  return list;
}

struct SampleRequest {
  std::string name;
  std::function<void(RiTarget&)> call;
};

template <typename Method, typename Values, typename... Rest>
void call_with(RiTarget& target, Method method, const Values& values, const Rest&... rest) {
  std::apply([&](const auto&... v) { (target.*method)(v..., rest...); }, values);
}

// One sample call of every request the list reads, writes and records generically.
std::vector<SampleRequest> sample_requests() {
  const SourceLoc loc;
  std::vector<SampleRequest> out;
#define DARC_RI_ON_ARG(Kind, name, what) sample(Kind{}),
#define DARC_RI_REQUEST(Rib, method, reading, shape, args)                                              \
  DARC_RI_IF_GENERIC_##reading(out.push_back({#Rib, [loc](RiTarget& t) {                                \
                                               call_with(t, &RiTarget::method, std::tuple{DARC_RI_EACH(args)}, loc); \
                                             }});)
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args)                                           \
  DARC_RI_IF_GENERIC_##reading(out.push_back({#Rib, [loc](RiTarget& t) {                                \
                                               call_with(t, &RiTarget::method, std::tuple{DARC_RI_EACH(args)}, \
                                                         sample_params(), loc);                         \
                                             }});)
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL
#undef DARC_RI_ON_ARG
  // Declare's second string is read as a declaration: it must be one.
  for (SampleRequest& r : out)
    if (r.name == "Declare") r.call = [loc](RiTarget& t) { t.declare("weight", "uniform float", loc); };
  return out;
}

std::string written(const std::function<void(RiTarget&)>& call) {
  std::ostringstream text;
  RibWriter writer(text);
  call(writer);
  return text.str();
}

// Parses `text` into a RibWriter; returns what it wrote, and the errors seen.
std::string reparsed(const std::string& text, std::vector<std::string>& errors) {
  std::ostringstream out;
  RibWriter writer(out);
  Diagnostics diag([&](const Diagnostic& d) {
    if (d.severity == Severity::Error) errors.push_back(d.message);
  });
  RibParser parser(writer, diag);
  parser.parse_string(text, "round-trip.rib");
  return out.str();
}

TEST(RiRequestList, EveryRequestRoundTripsParseWriteParse) {
  const std::vector<SampleRequest> requests = sample_requests();
  ASSERT_GT(requests.size(), 50u);
  for (const SampleRequest& r : requests) {
    SCOPED_TRACE(r.name);
    const std::string first = written(r.call);
    // The request's own name starts its line (after any indentation).
    EXPECT_EQ(first.find_first_not_of(' '), first.find(r.name)) << first;
    std::vector<std::string> errors;
    const std::string second = reparsed(first, errors);
    EXPECT_TRUE(errors.empty()) << first << (errors.empty() ? "" : errors.front());
    EXPECT_EQ(second, first);
    // And once more: the writer's output is a fixed point of parse and write.
    std::vector<std::string> more_errors;
    EXPECT_EQ(reparsed(second, more_errors), first);
  }
}

TEST(RiRequestList, EveryRequestIsRecordedAndReplayedUnchanged) {
  for (const SampleRequest& r : sample_requests()) {
    SCOPED_TRACE(r.name);
    std::vector<CallRecorder::Entry> kept;
    CallRecorder recorder([&](CallRecorder::Entry e) { kept.push_back(std::move(e)); });
    r.call(recorder);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0].request, r.name);
    std::ostringstream replayed;
    RibWriter writer(replayed);
    kept[0].call(writer);
    EXPECT_EQ(replayed.str(), written(r.call));
  }
}

// The table the parser reads requests with holds every `table` row of the list, and every
// request that goes through RiTarget::primitive.
TEST(RiRequestList, TheParserTableHoldsEveryTableRowAndEveryPrimitive) {
  std::vector<std::string> table_rows;
#define DARC_RI_REQUEST(Rib, method, reading, shape, args) DARC_RI_IF_TABLE_##reading(table_rows.push_back(#Rib);)
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args) DARC_RI_IF_TABLE_##reading(table_rows.push_back(#Rib);)
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL
  EXPECT_GT(table_rows.size(), 50u);
  for (const std::string& name : table_rows) EXPECT_NE(find_request_handler(name), nullptr) << name;
  for (const PrimitiveSignature& s : primitive_signatures())
    EXPECT_NE(find_request_handler(s.request), nullptr) << s.request;
  // The parser's own requests are not in the table (it reads them itself).
  EXPECT_EQ(find_request_handler("Option"), nullptr);
  EXPECT_EQ(find_request_handler("FrameBegin"), nullptr);
}

// Requests that take a parameter list write it, and a block request indents what follows.
TEST(RiRequestList, ParameterListsAndBlocksAreWritten) {
  std::ostringstream text;
  RibWriter writer(text);
  const SourceLoc loc;
  writer.world_begin(loc);
  writer.surface("matte", sample_params(), loc);
  writer.world_end(loc);
  EXPECT_EQ(text.str(), "WorldBegin\n  Surface \"matte\" \"uniform float weight\" [0.75]\nWorldEnd\n");
}

}  // namespace
}  // namespace darc
