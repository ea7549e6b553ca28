#include "parser/search_path.h"

namespace darc {

std::vector<std::string> expand_search_path(const std::string& spec, const std::vector<std::string>& previous,
                                            const std::vector<std::string>& defaults) {
  std::vector<std::string> dirs;
  size_t begin = 0;
  while (begin <= spec.size()) {
    size_t end = spec.find(':', begin);
    if (end == std::string::npos) end = spec.size();
    const std::string dir = spec.substr(begin, end - begin);
    if (dir == "&") {
      dirs.insert(dirs.end(), previous.begin(), previous.end());
    } else if (dir == "@") {
      dirs.insert(dirs.end(), defaults.begin(), defaults.end());
    } else if (!dir.empty()) {
      dirs.push_back(dir);
    }
    begin = end + 1;
  }
  return dirs;
}

}  // namespace darc
