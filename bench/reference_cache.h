// The speed-against-error benchmark's reference images, cached on disk: a stochastic render at
// many samples per pixel costs far more than every measured setting together, so it is kept
// in a cache directory under a key that changes whenever the scene text, the resolution or the
// reference settings change (a changed scene is then rendered anew, never compared with a stale
// reference).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "integrator/contribution.h"
#include "integrator/film.h"

namespace darc::bench {

struct ReferenceSettings {
  int samples_per_axis = 32;  // N x N jittered stochastic samples per pixel
  // Not the measured renders' seed (0): the reference's noise must be independent of theirs.
  uint32_t seed = 7919;
  // RenderOptions::contribution_threshold of the reference: the renderer's default, or 0 (every
  // secondary ray traced) for the secondary-ray report.
  float contribution_threshold = kDefaultContributionThreshold;
};

// 64-bit FNV-1a: a stable hash (std::hash may differ between library builds).
uint64_t fnv1a64(std::string_view bytes);

// The cache key: a hash of the scene text, the resolution and the reference settings, as 16
// hex digits. The contribution threshold enters the key only when it is not the renderer's
// default: the references cached before it was a setting were rendered at the default, and
// their keys stay valid (a 640x480 reference is hours of CPU).
std::string reference_cache_key(std::string_view scene_text, int xres, int yres, const ReferenceSettings& settings);

// "<dir>/<scene_name>-<key>.exr".
std::string reference_cache_path(const std::string& dir, const std::string& scene_name, const std::string& key);

// The cached reference at `path` if it exists, holds float R, G, B, A at xres x yres, and
// records `key`; nullopt otherwise (a miss, not an error).
std::optional<Image> load_cached_reference(const std::string& path, const std::string& key, int xres, int yres);

// Writes the R, G, B, A channels of `image` as a float EXR recording `key` (atomically: a
// temporary name, then rename). Returns an error message, empty on success.
std::string store_cached_reference(const std::string& path, const Image& image, const std::string& key);

}  // namespace darc::bench
