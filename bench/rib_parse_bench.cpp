// RIB reader throughput on a generated Curves-heavy scene (null target), and the cost of the
// Spirit X3 declaration grammar against a trivial hand-written split.
#include <benchmark/benchmark.h>

#include <charconv>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "parser/param_list.h"
#include "parser/rib_parser.h"

namespace darc {
namespace {

// Size of the generated scene: about the size of a real hair RIB chunk.
constexpr size_t kSceneBytes = 20u << 20;
// Strands per Curves request and control vertices per strand (a typical groom export).
constexpr int kStrandsPerCall = 100;
constexpr int kVerticesPerStrand = 10;

// Receives every request and does nothing, so the benchmark measures only reading.
class NullTarget : public RiTargetDefaults {
 public:
  size_t params_seen = 0;
  void option(const std::string&, const ParamList& p, const SourceLoc&) override { params_seen += p.params.size(); }
  void curves(const std::string&, const std::vector<int>&, const std::string&, const ParamList& p,
              const SourceLoc&) override {
    params_seen += p.params.size();
  }
};

void append_number(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 4);
  out.append(buf, r.ptr);
  out += ' ';
}

// A grass/hair scene: many Curves requests with P, width and Cs, as exporters write them.
std::string make_curves_scene(size_t bytes) {
  std::mt19937 rng(7);  // fixed seed: every run reads the same text
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  std::string rib = "##RenderMan RIB\nversion 3.04\nFormat 640 480 1\nProjection \"perspective\" \"fov\" [40]\n";
  rib += "WorldBegin\nBasis \"catmull-rom\" 1 \"catmull-rom\" 1\n";
  while (rib.size() < bytes) {
    rib += "AttributeBegin\nCurves \"cubic\" [";
    for (int s = 0; s < kStrandsPerCall; ++s) rib += std::to_string(kVerticesPerStrand) + " ";
    rib += "] \"nonperiodic\" \"P\" [";
    for (int i = 0; i < kStrandsPerCall * kVerticesPerStrand * 3; ++i) append_number(rib, coord(rng));
    rib += "]\n  \"varying float width\" [";
    for (int i = 0; i < kStrandsPerCall * (kVerticesPerStrand - 2); ++i) append_number(rib, 0.01);
    rib += "] \"uniform color Cs\" [";
    for (int i = 0; i < kStrandsPerCall * 3; ++i) append_number(rib, 0.5);
    rib += "]\nAttributeEnd\n";
  }
  rib += "WorldEnd\n";
  return rib;
}

void BM_ParseCurvesScene(benchmark::State& state) {
  const std::string rib = make_curves_scene(kSceneBytes);
  for (auto _ : state) {
    NullTarget target;
    Diagnostics diag([](const Diagnostic&) {});
    RibParser parser(target, diag);
    const bool ok = parser.parse_string(rib, "bench.rib");
    if (!ok) state.SkipWithError("parse failed");
    benchmark::DoNotOptimize(target.params_seen);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * rib.size()));
}
BENCHMARK(BM_ParseCurvesScene)->Unit(benchmark::kMillisecond);

const std::vector<std::string>& declaration_samples() {
  static const std::vector<std::string> samples = {
      "vertex point",   "varying float",  "uniform float[3]",     "constant color", " varying point[5]",
      "string",         "uniform string", "facevarying float[2]", "vertex hpoint",  "int",
      "constant float", "uniform normal", "varying color",        "uniform matrix", "float[4]"};
  return samples;
}

void BM_DeclarationX3(benchmark::State& state) {
  for (auto _ : state) {
    for (const std::string& s : declaration_samples()) benchmark::DoNotOptimize(parse_param_decl(s));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * declaration_samples().size()));
}
BENCHMARK(BM_DeclarationX3);

// The baseline: split on blanks, compare words, read "[n]" with from_chars. No validation
// beyond that, which is what makes it "trivial".
std::optional<ParamDecl> hand_split_decl(std::string_view text) {
  ParamDecl d;
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    const size_t begin = i;
    while (i < text.size() && text[i] != ' ') ++i;
    if (i > begin) words.push_back(text.substr(begin, i - begin));
  }
  if (words.empty() || words.size() > 2) return std::nullopt;
  if (words.size() == 2) {
    const std::string_view c = words[0];
    if (c == "constant")
      d.storage = StorageClass::Constant;
    else if (c == "uniform")
      d.storage = StorageClass::Uniform;
    else if (c == "varying")
      d.storage = StorageClass::Varying;
    else if (c == "vertex")
      d.storage = StorageClass::Vertex;
    else if (c == "facevarying")
      d.storage = StorageClass::FaceVarying;
    else
      return std::nullopt;
  }
  std::string_view t = words.back();
  if (const size_t bracket = t.find('['); bracket != std::string_view::npos) {
    std::from_chars(t.data() + bracket + 1, t.data() + t.size(), d.array_size);
    t = t.substr(0, bracket);
  }
  if (t == "float")
    d.type = ParamType::Float;
  else if (t == "int")
    d.type = ParamType::Integer;
  else if (t == "string")
    d.type = ParamType::String;
  else if (t == "color")
    d.type = ParamType::Color;
  else if (t == "point")
    d.type = ParamType::Point;
  else if (t == "normal")
    d.type = ParamType::Normal;
  else if (t == "hpoint")
    d.type = ParamType::HPoint;
  else if (t == "matrix")
    d.type = ParamType::Matrix;
  else
    return std::nullopt;
  return d;
}

void BM_DeclarationHandSplit(benchmark::State& state) {
  for (auto _ : state) {
    for (const std::string& s : declaration_samples()) benchmark::DoNotOptimize(hand_split_decl(s));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * declaration_samples().size()));
}
BENCHMARK(BM_DeclarationHandSplit);

}  // namespace
}  // namespace darc

BENCHMARK_MAIN();
