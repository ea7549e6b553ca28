// A position in RIB source text, carried by every token, request and parameter so that any
// later error (in the parser or the scene builder) can point at the file, line and column.
#pragma once

#include <memory>
#include <string>

namespace darc {

struct SourceLoc {
  std::shared_ptr<const std::string> file;  // shared: thousands of tokens point at one name
  int line = 0;                             // 1-based; 0 means "no position"
  int column = 0;                           // 1-based

  std::string file_name() const { return file ? *file : std::string("<unknown>"); }
  // "file:line:col"
  std::string str() const;
};

}  // namespace darc
