// RI search paths: Option "searchpath" values such as "a:b:&:@", split into folders.
#pragma once

#include <string>
#include <vector>

namespace darc {

// Splits a search path "a:b:&:@" replacing "&" by the previous path's folders and "@" by the
// default ones; empty entries are dropped.
std::vector<std::string> expand_search_path(const std::string& spec, const std::vector<std::string>& previous,
                                            const std::vector<std::string>& defaults);

}  // namespace darc
