// The --stats JSON file: {"software": "darc VERSION", "frames": [...]}, one entry per rendered
// frame. Written like the images (a temporary name, then renamed), so that a reader never sees
// half a file, even from a render that was stopped while writing it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace darc {

// Writes `frames` (a JSON array of per-frame entries) to `path`. Returns an error message, or
// "" when the file was written.
std::string write_stats_file(const std::string& path, const nlohmann::json& frames);

}  // namespace darc
