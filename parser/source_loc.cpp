#include "parser/source_loc.h"

namespace darc {

std::string SourceLoc::str() const {
  return file_name() + ":" + std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace darc
