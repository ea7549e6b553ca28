#include "parser/request_table.h"

#include "parser/primitive_signatures.h"

#include <array>
#include <tuple>
#include <unordered_map>

namespace darc {

namespace {

using Ctx = RequestContext;

// Reads fixed arguments by their kind (parser/ri_arg_kinds.h), `what` naming each in messages.
class ArgReader {
 public:
  explicit ArgReader(RequestReader& args) : args_(args) {}

  int read(RiInt, const char* what) { return args_.integer(what); }
  double read(RiFloat, const char* what) { return args_.number(what); }
  bool read(RiBool, const char* what) { return args_.integer(what) != 0; }
  std::string read(RiString, const char* what) { return args_.string(what); }
  std::string read(RiHandle, const char* what) { return args_.handle(what); }
  std::array<double, 16> read(RiMatrix, const char* what) { return args_.numbers<16>(what); }
  std::array<float, 3> read(RiColor, const char* what) {
    const std::array<double, 3> v = args_.numbers<3>(what);
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
  }
  BasisArg read(RiBasis, const char* what) { return args_.basis(what); }
  std::vector<int> read(RiIntArray, const char* what) { return args_.integer_array(what); }
  std::vector<double> read(RiFloatArray, const char* what) { return args_.number_array(what); }
  // A run of N numbers is read whole at its first, then handed out one by one.
  template <int N>
  double read(RiNumbers<N>, const char* what) {
    run_ = args_.fixed_numbers(N, what);
    next_ = 1;
    return run_[0];
  }
  double read(RiNumbersNext, const char*) { return run_.at(next_++); }

 private:
  RequestReader& args_;
  std::vector<double> run_;
  size_t next_ = 0;
};

// Calls `method` of the target with the values read (a tuple, in the order of the request's
// arguments) and `rest...` (the parameter list when there is one, then the position).
template <typename Method, typename Values, typename... Rest>
void call_target(RiTarget& target, Method method, const Values& values, const Rest&... rest) {
  std::apply([&](const auto&... v) { (target.*method)(v..., rest...); }, values);
}

// --- requests without effect: arguments flattened, any parameter list checked and dropped ---

void ignored(Ctx& c) {
  std::vector<double> numbers;
  std::vector<std::string> strings;
  c.args.flatten_rest(numbers, strings);
  c.target.ignored_request(c.name, numbers, strings, c.loc);
}

// An ignored request with FixedStrings leading strings, then FixedNumbers numbers, then a plist.
template <int FixedStrings, int FixedNumbers>
void ignored_with_params(Ctx& c) {
  std::vector<double> numbers;
  std::vector<std::string> strings;
  for (int i = 0; i < FixedStrings; ++i) strings.push_back(c.args.string("a fixed argument"));
  for (int i = 0; i < FixedNumbers; ++i) numbers.push_back(c.args.number("a fixed argument"));
  c.args.skip_param_list(c.name);
  c.target.ignored_request(c.name, numbers, strings, c.loc);
}

// --- the requests of parser/ri_requests.def the table reads: one reader each ---
// The values are read into a braced list, whose elements C++ evaluates in order (a function's
// arguments would be evaluated in any order).
#define DARC_RI_ON_ARG(Kind, name, what) r.read(Kind{}, what),
#define DARC_RI_REQUEST(Rib, method, reading, shape, arg_seq) \
  DARC_RI_IF_TABLE_##reading(void read_##method(Ctx& c) {  \
    ArgReader r(c.args);                                  \
    const auto values = std::tuple{DARC_RI_EACH(arg_seq)};   \
    c.args.expect_request_end(#Rib);                      \
    call_target(c.target, &RiTarget::method, values, c.loc); \
  })
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, arg_seq)                               \
  DARC_RI_IF_TABLE_##reading(void read_##method(Ctx& c) {                                  \
    ArgReader r(c.args);                                                                  \
    const auto values = std::tuple{DARC_RI_EACH(arg_seq)};                                   \
    call_target(c.target, &RiTarget::method, values, c.args.param_list(c.name), c.loc); \
  })
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL
#undef DARC_RI_ON_ARG

// --- geometry ---

// Sphere, the other quadrics, the patches, NuPatch, SubdivisionMesh, Points: read by their
// signature into one PrimitiveRequest.
void primitive(Ctx& c) {
  const PrimitiveSignature* signature = find_primitive_signature(c.name);
  PrimitiveRequest r;
  r.name = c.name;
  const auto args = signature->args;
  for (size_t i = 0; i < args.size(); ++i) {
    const PrimitiveArgSpec& a = args[i];
    if (a.optional && !c.args.at_array()) continue;
    switch (a.type) {
      case PrimitiveArgType::Number: {
        // A run of numbers may be written bare or as one bracketed array (Sphere [1 -1 1 360]).
        size_t n = 1;
        while (i + n < args.size() && args[i + n].type == PrimitiveArgType::Number) ++n;
        std::string what = a.name;
        for (size_t k = 1; k < n; ++k) what += std::string(k + 1 == n ? " and " : ", ") + args[i + k].name;
        const std::vector<double> v = c.args.fixed_numbers(n, what.c_str());
        r.numbers.insert(r.numbers.end(), v.begin(), v.end());
        i += n - 1;
        break;
      }
      case PrimitiveArgType::Integer: r.numbers.push_back(c.args.integer(a.name)); break;
      case PrimitiveArgType::String: r.strings.push_back(c.args.string(a.name)); break;
      case PrimitiveArgType::IntegerArray: r.integer_arrays.push_back(c.args.integer_array(a.name)); break;
      case PrimitiveArgType::NumberArray: r.number_arrays.push_back(c.args.number_array(a.name)); break;
      case PrimitiveArgType::StringArray: r.string_arrays.push_back(c.args.string_array(a.name)); break;
    }
  }
  c.target.primitive(r, c.args.param_list(c.name), c.loc);
}

using Table = std::unordered_map<std::string_view, RequestHandler>;

Table make_table() {
  Table table{
#define DARC_RI_REQUEST(Rib, method, reading, shape, args) DARC_RI_IF_TABLE_##reading({#Rib, read_##method}, )
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args) DARC_RI_IF_TABLE_##reading({#Rib, read_##method}, )
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL
      // Accepted without effect.
      {"ShadingRate", ignored},
      {"ShadingInterpolation", ignored},
      {"RelativeDetail", ignored},
      {"PixelVariance", ignored},
      {"ColorSamples", ignored},
      {"Matte", ignored},
      {"Bound", ignored},
      {"Detail", ignored},
      {"DetailRange", ignored},
      {"GeometricApproximation", ignored},
      {"TextureCoordinates", ignored},
      {"ArchiveRecord", ignored},
      {"Skew", ignored},
      {"Imager", ignored_with_params<1, 0>},
      {"Atmosphere", ignored_with_params<1, 0>},
      {"Interior", ignored_with_params<1, 0>},
      {"Exterior", ignored_with_params<1, 0>},
      {"MakeShadow", ignored_with_params<2, 0>},
      // MakeTexture "pic" "tex" swrap twrap filter swidth twidth plist
      {"MakeTexture", ignored_with_params<5, 2>},
  };
  // Sphere, the other quadrics, the patches, NuPatch, SubdivisionMesh, Points.
  for (const PrimitiveSignature& signature : primitive_signatures()) table.emplace(signature.request, primitive);
  return table;
}

}  // namespace

RequestHandler find_request_handler(std::string_view name) {
  static const Table table = make_table();  // built once, read-only afterwards
  const auto it = table.find(name);
  return it == table.end() ? nullptr : it->second;
}

}  // namespace darc
