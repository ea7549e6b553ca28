#include "parser/rib_writer.h"

#include "parser/primitive_signatures.h"
#include "parser/ri_request_macros.h"

#include <charconv>
#include <type_traits>

namespace darc {

namespace {

// Spaces per block level.
constexpr int kIndentWidth = 2;

template <typename T>
std::string shortest(T v) {
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, result.ptr);
}

template <typename Range>
std::string bracketed(const Range& values) {
  std::string s = "[";
  bool first = true;
  for (const auto& v : values) {
    if (!first) s += ' ';
    first = false;
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) {
      s += rib_string(v);
    } else if constexpr (std::is_same_v<std::decay_t<decltype(v)>, int>) {
      s += std::to_string(v);
    } else {
      s += rib_number(v);
    }
  }
  return s + "]";
}

// One fixed argument, by its kind (parser/ri_arg_kinds.h), with the space before it.
void write_arg(std::ostream& out, RiInt, int v) { out << ' ' << v; }
void write_arg(std::ostream& out, RiFloat, double v) { out << ' ' << rib_number(v); }
template <int N>
void write_arg(std::ostream& out, RiNumbers<N>, double v) { out << ' ' << rib_number(v); }
void write_arg(std::ostream& out, RiNumbersNext, double v) { out << ' ' << rib_number(v); }
void write_arg(std::ostream& out, RiBool, bool v) { out << ' ' << (v ? 1 : 0); }
void write_arg(std::ostream& out, RiString, const std::string& v) { out << ' ' << rib_string(v); }
void write_arg(std::ostream& out, RiMatrix, const std::array<double, 16>& v) { out << ' ' << bracketed(v); }
void write_arg(std::ostream& out, RiColor, const std::array<float, 3>& v) { out << ' ' << bracketed(v); }
void write_arg(std::ostream& out, RiIntArray, const std::vector<int>& v) { out << ' ' << bracketed(v); }
void write_arg(std::ostream& out, RiFloatArray, const std::vector<double>& v) { out << ' ' << bracketed(v); }

// A handle that was written as an integer is written back as one.
std::string rib_handle(const std::string& handle) {
  const bool integer = !handle.empty() && handle.size() < 10 &&
                       handle.find_first_not_of("0123456789") == std::string::npos &&
                       (handle == "0" || handle.front() != '0');
  return integer ? handle : rib_string(handle);
}

void write_arg(std::ostream& out, RiHandle, const std::string& v) { out << ' ' << rib_handle(v); }

void write_arg(std::ostream& out, RiBasis, const BasisArg& b) {
  out << ' ' << (b.name.empty() ? bracketed(b.matrix) : rib_string(b.name));
}

}  // namespace

std::string rib_number(double v) { return shortest(v); }
std::string rib_number(float v) { return shortest(v); }

std::string rib_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        out += c;
    }
  }
  return out + "\"";
}

std::ostream& RibWriter::begin_line(const char* request) {
  out_ << std::string(static_cast<size_t>(depth_ * kIndentWidth), ' ') << request;
  return out_;
}

std::ostream& RibWriter::begin_request(const char* request, RequestShape shape) {
  if (shape == RequestShape::close && depth_ > 0) --depth_;
  std::ostream& out = begin_line(request);
  if (shape == RequestShape::open) ++depth_;
  return out;
}

void RibWriter::write_params(const ParamList& params) {
  for (const Param& p : params.params) {
    out_ << ' ' << rib_string(to_string(p.decl) + " " + p.name) << ' ';
    if (p.decl.is_string()) {
      out_ << bracketed(p.strings);
    } else {
      out_ << bracketed(p.floats);
    }
  }
  out_ << '\n';
}

// Every request of parser/ri_requests.def but the special ones: its name, its arguments by kind,
// its parameter list, one line.
#define DARC_RI_ON_ARG(Kind, name, what) write_arg(out, Kind{}, name);
#define DARC_RI_REQUEST(Rib, method, reading, shape, args)                      \
  DARC_RI_IF_GENERIC_##reading(                                                 \
      void RibWriter::method(DARC_RI_PARAMS(args) const SourceLoc&) {           \
        [[maybe_unused]] std::ostream& out = begin_request(#Rib, RequestShape::shape); \
        DARC_RI_EACH(args)                                                      \
        out << '\n';                                                            \
      })
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args)                   \
  DARC_RI_IF_GENERIC_##reading(                                                 \
      void RibWriter::method(DARC_RI_PARAMS(args) const ParamList& params,      \
                             const SourceLoc&) {                                \
        [[maybe_unused]] std::ostream& out = begin_request(#Rib, RequestShape::shape); \
        DARC_RI_EACH(args)                                                      \
        write_params(params);                                                   \
      })
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL
#undef DARC_RI_ON_ARG

// --- the special rows ---

void RibWriter::ignored_request(const std::string& request, const std::vector<double>& numbers,
                                const std::vector<std::string>& strings, const SourceLoc&) {
  // Strings first, then numbers: the order of every ignored request's fixed arguments.
  std::ostream& line = begin_line(request.c_str());
  for (const std::string& s : strings) line << ' ' << rib_string(s);
  for (double v : numbers) line << ' ' << rib_number(v);
  line << '\n';
}

void RibWriter::primitive(const PrimitiveRequest& r, const ParamList& params, const SourceLoc&) {
  std::ostream& out = begin_line(r.name.c_str());
  size_t number = 0, string = 0, ints = 0, numbers = 0, strings = 0;
  // The typed lists are written back in the order of the request's signature; optional arrays
  // that were left out are not in the lists.
  const PrimitiveSignature* signature = find_primitive_signature(r.name);
  for (const PrimitiveArgSpec& a : signature ? signature->args : std::span<const PrimitiveArgSpec>{}) {
    switch (a.type) {
      case PrimitiveArgType::Number:
      case PrimitiveArgType::Integer:
        if (number < r.numbers.size()) out << ' ' << rib_number(r.numbers[number++]);
        break;
      case PrimitiveArgType::String:
        if (string < r.strings.size()) out << ' ' << rib_string(r.strings[string++]);
        break;
      case PrimitiveArgType::IntegerArray:
        if (ints < r.integer_arrays.size()) out << ' ' << bracketed(r.integer_arrays[ints++]);
        break;
      case PrimitiveArgType::NumberArray:
        if (numbers < r.number_arrays.size()) out << ' ' << bracketed(r.number_arrays[numbers++]);
        break;
      case PrimitiveArgType::StringArray:
        if (strings < r.string_arrays.size()) out << ' ' << bracketed(r.string_arrays[strings++]);
        break;
    }
  }
  write_params(params);
}

// Not written: the parser has already warned, and its arguments are gone.
void RibWriter::skipped_primitive(const std::string&, const SourceLoc&) {}

}  // namespace darc
