#include "python/python_params.h"

#include <pybind11/numpy.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace darc::python {

namespace {

bool is_text(const py::handle& value) { return py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value); }

// Strings, when `values` is a string or a sequence of them.
bool holds_strings(const py::handle& values) {
  if (is_text(values)) return true;
  if (py::isinstance<py::list>(values) || py::isinstance<py::tuple>(values)) {
    const py::sequence seq = py::reinterpret_borrow<py::sequence>(values);
    return seq.size() > 0 && is_text(seq[0]);
  }
  return false;
}

}  // namespace

std::vector<std::string> strings(const py::handle& values) {
  if (is_text(values)) return {py::cast<std::string>(values)};
  std::vector<std::string> out;
  for (const py::handle item : values) out.push_back(py::cast<std::string>(item));
  return out;
}

std::vector<double> doubles(const py::handle& values) {
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!array) throw py::type_error("expected numbers");
  return std::vector<double>(array.data(), array.data() + array.size());
}

std::vector<int> ints(const py::handle& values) {
  const auto array = py::array_t<int, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!array) throw py::type_error("expected integers");
  return std::vector<int>(array.data(), array.data() + array.size());
}

ParamList param_list(RiSession& session, const char* request, const py::dict& params, const SourceLoc& loc) {
  ParamList list;
  list.params.reserve(params.size());
  for (const auto& [key, value] : params) {
    Param param;
    param.loc = loc;
    std::optional<ParamDecl> decl = parse_inline_decl(py::cast<std::string>(key), param.name);
    if (!decl) decl = session.declared_type(param.name);
    if (holds_strings(value)) {
      param.strings = strings(value);
    } else {
      // float32 and C-contiguous already (numpy's default for a float32 array): no copy here.
      const auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(value);
      if (!array) throw py::type_error(fmt::format("{}: parameter \"{}\": expected numbers or strings", request, param.name));
      param.floats.resize(size_t(array.size()));
      if (array.size() > 0) std::memcpy(param.floats.data(), array.data(), param.floats.size() * sizeof(float));
    }
    if (!decl) {
      ParamDecl inferred;
      if (!param.strings.empty()) inferred.type = ParamType::String;
      else inferred.array_size = std::max<int>(1, int(param.floats.size()));
      session.diagnostics().warning_once(
          "undeclared parameter " + param.name, loc, request,
          fmt::format("parameter \"{}\" is not declared: assuming \"{}\"", param.name, to_string(inferred)));
      decl = inferred;
    }
    param.decl = *decl;
    if ((param.decl.is_string() && !param.floats.empty()) || (!param.decl.is_string() && !param.strings.empty())) {
      session.diagnostics().error(loc, request,
                                  fmt::format("\"{}\": expected {} for a {} parameter: left out", param.name,
                                              param.decl.is_string() ? "strings" : "numbers", to_string(param.decl)));
      continue;
    }
    if (!param.decl.is_string() && param.floats.size() % size_t(param.decl.components()) != 0) {
      session.diagnostics().error(loc, request,
                                  fmt::format("\"{}\": {} values must come in groups of {}, found {}: left out",
                                              param.name, to_string(param.decl), param.decl.components(),
                                              param.floats.size()));
      continue;
    }
    list.params.push_back(std::move(param));
  }
  return list;
}

}  // namespace darc::python
