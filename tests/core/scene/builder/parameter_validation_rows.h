// The rows of the numeric parameter audit (docs/parameters.md) and what they are made of, shared
// by parameter_validation_test.cpp (the table's test, and most rows) and the files that hold the
// rows of one subject (parameter_validation_motion_rows.cpp).
#pragma once

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "support/scenes_from_rib.h"

namespace darc::test {

struct Expected {
  Severity severity;
  int line, column;
  std::string request;
  std::string message;
};

inline Expected error(int line, const std::string& request, const std::string& message) {
  return {Severity::Error, line, 1, request, message};
}
inline Expected warning(int line, const std::string& request, const std::string& message) {
  return {Severity::Warning, line, 1, request, message};
}

struct Row {
  std::string id;  // the ID column of docs/parameters.md
  std::string rib;
  std::optional<Expected> expected;  // nullopt: a valid value, nothing is reported
  std::function<void(const Scene&)> result;
};

// gtest names a failing row by its ID, not by its bytes.
inline void PrintTo(const Row& row, std::ostream* os) { *os << row.id; }

// `requests` start on line 1, before an empty world block.
inline std::string before_world(const std::string& requests) { return requests + "\nWorldBegin\nWorldEnd\n"; }
// `requests` start on line 2, inside the world block.
inline std::string in_world(const std::string& requests) { return "WorldBegin\n" + requests + "\nWorldEnd\n"; }

// The name build() gives its text in messages.
inline const std::string kRibName = "test.rib";
inline const std::string kLine3 = "Curves \"linear\" [3] \"nonperiodic\" \"P\" [0 0 0  1 0 0  2 0 0]";

// Motion blocks, the shutter and its opening (parameter_validation_motion_rows.cpp).
std::vector<Row> motion_rows();

}  // namespace darc::test
