#include "support/shared_ribs.h"

namespace darc::test {

std::filesystem::path shared_ribs(const std::string& folder) {
  return std::filesystem::path(DARC_SHARED_RIBS_DIR) / folder;
}

}  // namespace darc::test
