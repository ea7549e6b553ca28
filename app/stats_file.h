// The --stats JSON file: {"software": "darc VERSION", "frames": [...]}, one entry per rendered
// frame. Written like the images (a temporary name, then renamed), so that a reader never sees
// half a file, even from a render that was stopped while writing it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace darc {

// Writes `frames` (a JSON array of per-frame entries) to `path`, with the members of `run` (an
// object: figures of the whole run so far, such as the archive cache's) beside them. Returns an
// error message, or "" when the file was written.
std::string write_stats_file(const std::string& path, const nlohmann::json& frames,
                             const nlohmann::json& run = nlohmann::json::object());

// A frame's "integrator" entry for a file with a RenderMan Integrator request: the integrator
// the file named, and that darc's own was used (darc has one integrator per hider).
nlohmann::json integrator_json(const std::string& requested);

}  // namespace darc
