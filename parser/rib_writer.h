// An RiTarget that prints every call as canonical RIB (darc --cat): one request per line,
// two-space indentation inside Frame/World/Attribute/Transform/Object blocks, every parameter
// with its full inline declaration ("vertex point P"), numbers in the shortest spelling that
// reads back to the same value. Parsing its output again gives the same calls and text.
#pragma once

#include <ostream>
#include <string>

#include "parser/ri_target.h"

namespace darc {

class RibWriter : public RiTarget {
 public:
  explicit RibWriter(std::ostream& out) : out_(out) {}

#include "parser/ri_target_overrides.inc"

 private:
  // Starts a request line at the current indentation.
  std::ostream& begin_line(const char* request);
  // Starts a request line, indenting after a block opens and before it closes.
  std::ostream& begin_request(const char* request, RequestShape shape);
  void write_params(const ParamList& params);

  std::ostream& out_;
  int depth_ = 0;
};

// Formatting helpers, shared with tests: shortest round-trip numbers and escaped strings.
std::string rib_number(double v);
std::string rib_number(float v);
std::string rib_string(const std::string& s);  // with quotes and escapes

}  // namespace darc
