// Python values into the values an RiTarget takes: a parameter dictionary into a ParamList, and
// number sequences (lists, tuples or numpy arrays of any numeric type) into vectors. Numbers are
// read through numpy's buffer protocol, so a large array costs one conversion pass, not one
// Python call per element.
#pragma once

#include "parser/diagnostics.h"
#include "parser/param_list.h"
#include "ri/ri_session.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace darc::python {

namespace py = pybind11;

// {"P": points, "constantwidth": 0.01, "uniform color tint": [1, 0, 0], "string name": "x"}:
// each key typed by its inline declaration, RiDeclare or the standard declarations; an
// undeclared key is typed from its values with a warning, as the RIB parser types it.
ParamList param_list(RiSession& session, const char* request, const py::dict& params, const SourceLoc& loc);

std::vector<double> doubles(const py::handle& values);
std::vector<int> ints(const py::handle& values);
std::vector<std::string> strings(const py::handle& values);

}  // namespace darc::python
