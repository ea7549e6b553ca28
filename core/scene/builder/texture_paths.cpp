#include "core/scene/builder/texture_paths.h"

#include "core/scene/ris/color_texture_params.h"

#include <filesystem>

#include "parser/search_path.h"

namespace darc {

namespace fs = std::filesystem;

namespace {

fs::path folder_of(const std::string& rib_file) {
  std::error_code ec;
  fs::path dir = fs::path(rib_file).parent_path();
  if (dir.empty()) dir = fs::current_path(ec);
  return fs::absolute(dir, ec);
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

}  // namespace

std::vector<std::string> texture_search_path(const std::vector<std::string>& specs,
                                             const std::vector<std::string>& previous, const std::string& rib_file) {
  std::vector<std::string> dirs;
  for (const std::string& spec : specs)
    for (const std::string& dir : expand_search_path(spec, previous, {})) {
      const fs::path p(dir);
      // Folders from '&' are absolute already.
      dirs.push_back(p.is_absolute() ? p.string() : (folder_of(rib_file) / p).lexically_normal().string());
    }
  return dirs;
}

std::optional<std::string> find_texture(const std::string& name, const std::vector<std::string>& search_path,
                                        const std::string& rib_file) {
  if (name.empty()) return std::nullopt;
  const fs::path p(name);
  if (p.is_absolute()) return is_file(p) ? std::optional(p.string()) : std::nullopt;
  for (const std::string& dir : search_path)
    if (const fs::path candidate = fs::path(dir) / p; is_file(candidate)) return candidate.lexically_normal().string();
  if (const fs::path beside = folder_of(rib_file) / p; is_file(beside)) return beside.lexically_normal().string();
  std::error_code ec;
  if (is_file(p)) return fs::absolute(p, ec).lexically_normal().string();
  return std::nullopt;
}

bool names_a_texture(const std::string& shader, const Param& param) {
  if (param.decl.type != ParamType::String) return false;
  if (param.name == kColorTextureParam) return true;  // any shader's PxrTexture colour
  if (shader == "domelight" || shader == "envlight") return param.name == "mapname" || param.name == "envname";
  return shader == "paintedplastic" && param.name == "texturename";
}

}  // namespace darc
