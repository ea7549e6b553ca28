// Finding texture files: RI Option "searchpath" "texture" (folders separated by ':', '&' for the
// previous path), folders relative to the RIB file that gave the option; a name is looked up as
// given when absolute, else along the search path, then beside the RIB file that names it, then
// in the working directory. The shaders receive absolute paths, so nothing depends on where
// darc runs or on OpenImageIO's own search path.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "parser/param_list.h"

namespace darc {

// The search path `spec` gives ("a:b:&"), relative folders made absolute from `rib_file`'s folder,
// '&' replaced by `previous`.
std::vector<std::string> texture_search_path(const std::vector<std::string>& specs,
                                             const std::vector<std::string>& previous, const std::string& rib_file);

// The file `name` denotes, or nullopt when there is none.
std::optional<std::string> find_texture(const std::string& name, const std::vector<std::string>& search_path,
                                        const std::string& rib_file);

// The shader parameters that name a texture file (paintedplastic's "texturename", the dome's
// "mapname" or "envname").
bool names_a_texture(const std::string& shader, const Param& param);

}  // namespace darc
