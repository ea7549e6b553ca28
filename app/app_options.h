// The darc command line, parsed (DESIGN.md "Command-line contract").
#pragma once

#include "app/frame_list.h"
#include "integrator/render_frame.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace darc {

struct AppOptions {
  std::vector<std::string> inputs;  // RIB files, "-" for stdin
  std::string output;               // -o: overrides the Display name
  std::string preview;              // --preview: also write an 8-bit preview (PNG/TIFF/JPEG)
  int xres = 0, yres = 0;           // --res
  // --crop xmin xmax ymin ymax: the CropWindow of every frame, whatever the RIB says (NDC, as
  // CropWindow; prman -crop).
  std::optional<std::array<double, 4>> crop;
  HiderKind hider = HiderKind::Distance;
  int pixel_samples = 0;            // --pixel-samples N (N x N); 0 keeps PixelSamples
  int threads = 0;
  std::optional<float> contribution_threshold;  // --contribution-threshold (unset: the default)
  bool area_light_cones = true;  // --area-shadows cone (default) | sampled
  std::optional<FrameList> frames;
  bool skip_existing = false;
  bool strict = false;              // --strict: ErrorHandler "abort" for the whole run, whatever the RIB says
  std::string stats_path;
  uint32_t seed = 0;
  bool quiet = false;
  bool progress = false;  // force progress even when quiet would hide it
  bool cat = false;       // --cat: print the parsed RIB instead of rendering
  std::string ocio_config;
  // --memory-limit: the memory darc may use in all. Unset: the smallest limit Linux gives this
  // process (app/memory_limit.h); 0 (--memory-limit none): no limit.
  std::optional<uint64_t> memory_limit_bytes;
  bool archive_cache = true;  // --no-archive-cache: parse every ReadArchive again (for comparison)
  // --procedural-path (repeatable) and DARC_PROCEDURAL_PATH (colon-separated): the folders the
  // user allows Procedural "RunProgram" to start programs from; the RIB's Option "searchpath"
  // "procedural" may only narrow them (parser/procedural_folders.h).
  std::vector<std::string> procedural_paths;
  std::vector<std::string> procedural_env_paths;
  // --trust-rib: the user trusts the RIB files: their procedural search path may widen the
  // user's folders and their Display names may leave the working folder.
  bool trust_rib = false;
  double procedural_timeout_seconds = 60;  // --procedural-timeout: per RunProgram request
  // --disk-reserve: the free space an image write must leave on its file system (0: none).
  // Unset: app/disk_reserve.h's default, 1 % of the file system up to 1 GiB.
  std::optional<uint64_t> disk_reserve_bytes;
};

// Exit codes (DESIGN.md).
enum ExitCode { kExitOk = 0, kExitRenderError = 1, kExitUsage = 2, kExitSceneError = 3 };

// Parses argv. On --help/--version prints and sets exit_now = true with code 0; on a usage
// error prints the message and returns kExitUsage with exit_now = true.
AppOptions parse_command_line(int argc, char** argv, bool& exit_now, int& exit_code);

}  // namespace darc
