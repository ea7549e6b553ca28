#include "app/stats_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace darc {

namespace fs = std::filesystem;

std::string write_stats_file(const std::string& path, const nlohmann::json& frames, const nlohmann::json& run) {
  nlohmann::json document{{"software", std::string("darc ") + DARC_VERSION}};
  if (run.is_object()) document.update(run);
  document["frames"] = frames;
  // The process id keeps two darc runs writing the same name from sharing a temporary file.
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream f(temporary);
    if (!f) return std::strerror(errno);
    f << document.dump(2) << "\n";
    f.close();
    if (!f) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      return "write failed";
    }
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return ec.message();
  }
  return {};
}

nlohmann::json integrator_json(const std::string& requested) {
  return {{"requested", requested},
          {"used", "darc"},
          {"note", "darc renders with its own integrator; the requested one and its parameters were not used"}};
}

}  // namespace darc
