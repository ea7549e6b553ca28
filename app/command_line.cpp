#include "app/app_options.h"
#include "app/memory_limit.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace darc {

namespace {

// Largest --res side we accept: far beyond any film we render, small enough that W*H pixels of
// RGBA float stay addressable.
constexpr int kMaxResolution = 16384;

// Longest --procedural-timeout: a day, far past any generator, and well inside what the
// millisecond clock of the time limit holds.
constexpr double kMaxProceduralTimeoutSeconds = 86400;

// Parses a positive integer that fills `text` exactly (no sign, spaces or trailing characters).
bool parse_positive_int(std::string_view text, int& value) {
  if (text.empty() || text.front() < '0' || text.front() > '9') return false;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && value >= 1;
}

// "WxH" (or "WXH") with both sides in [1, kMaxResolution]; anything else ("10", "10x",
// "10x10junk", " 10x10") is rejected rather than half-read.
bool parse_resolution(std::string_view text, int& width, int& height) {
  const size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return false;
  int w = 0, h = 0;
  if (!parse_positive_int(text.substr(0, x), w) || !parse_positive_int(text.substr(x + 1), h)) return false;
  if (w > kMaxResolution || h > kMaxResolution) return false;
  width = w;
  height = h;
  return true;
}

// --crop's four values, when they make a crop window as CropWindow's rule has it (RI Spec 3.2:
// 0 <= xmin < xmax <= 1 and the same for y); whether it keeps a pixel is checked per frame, once
// the resolution is known.
std::optional<std::array<double, 4>> parse_crop(const std::vector<double>& v) {
  auto in01 = [](double x) { return x >= 0 && x <= 1; };
  if (v.size() != 4 || !std::ranges::all_of(v, in01) || v[0] >= v[1] || v[2] >= v[3]) return std::nullopt;
  return std::array<double, 4>{v[0], v[1], v[2], v[3]};
}

// "a:b::c" -> {a, b, c}: a colon-separated list of folders, as PATH is written.
std::vector<std::string> split_folder_list(std::string_view list) {
  std::vector<std::string> folders;
  size_t begin = 0;
  while (begin <= list.size()) {
    size_t end = list.find(':', begin);
    if (end == std::string_view::npos) end = list.size();
    if (end > begin) folders.emplace_back(list.substr(begin, end - begin));
    begin = end + 1;
  }
  return folders;
}

}  // namespace

AppOptions parse_command_line(int argc, char** argv, bool& exit_now, int& exit_code) {
  AppOptions o;
  exit_now = false;
  exit_code = kExitOk;
  CLI::App app{"darc: distance-aware ray tracing of RenderMan curves"};
  app.set_version_flag("--version", std::string("darc ") + DARC_VERSION);
  app.add_option("files", o.inputs, "RIB files ('-' reads standard input)")->required();
  app.add_option("-o,--output", o.output, "output file (overrides Display; '#' run or %04d takes the frame number)");
  app.add_option("--preview", o.preview, "also write an 8-bit preview through the OCIO display transform");
  std::string res;
  app.add_option("--res", res, "resolution WxH (overrides Format)");
  std::vector<double> crop;
  app.add_option("--crop", crop,
                 "render only the part xmin xmax ymin ymax of the image (fractions, 0 <= xmin < xmax <= 1, as "
                 "CropWindow, which it overrides): the file keeps the full display window, the crop is its data "
                 "window")
      ->expected(4)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::Throw);
  std::string hider = "distance";
  app.add_option("--hider", hider, "distance (default) | stochastic")->check(CLI::IsMember({"distance", "stochastic"}));
  app.add_option("--pixel-samples", o.pixel_samples, "N x N samples per pixel (overrides PixelSamples)")
      ->check(CLI::Range(1, 64));
  app.add_option("--threads", o.threads, "threads, 0 = all cores")->check(CLI::Range(0, 1024));
  float contribution_threshold = -1;
  app.add_option("--contribution-threshold", contribution_threshold,
                 "secondary rays that can change the pixel by less than this are not traced (0: trace all; "
                 "default " + std::to_string(kDefaultContributionThreshold) + ")")
      ->check(CLI::Range(0.0f, 1.0f));
  std::string area_shadows = "cone";
  app.add_option("--area-shadows", area_shadows,
                 "distance hider, lights with extent: one cone shadow ray from the receiving footprint to the "
                 "light (cone, default) | a footprint shadow ray per light sample (sampled)")
      ->check(CLI::IsMember({"cone", "sampled"}));
  std::string frames;
  app.add_option("--frames", frames, "frames to render, e.g. 1-10,15,20-40x5");
  app.add_flag("--skip-existing", o.skip_existing,
               "skip frames whose output file already exists (and records no errors)");
  app.add_flag("--strict", o.strict,
               "stop at the first scene error and write nothing for its frame (ErrorHandler \"abort\", "
               "overriding the RIB's ErrorHandler)");
  app.add_option("--stats", o.stats_path, "write per-frame timings and counters as JSON");
  app.add_option("--seed", o.seed, "random seed");
  app.add_flag("-q,--quiet", o.quiet, "no progress output");
  app.add_flag("--progress", o.progress, "progress output even when not wanted by default");
  app.add_flag("--cat", o.cat, "print the parsed RIB (canonical form) instead of rendering");
  app.add_option("--ocio-config", o.ocio_config,
                 "OpenColorIO config for 8-bit outputs (default: $OCIO, else built in)");
  bool no_archive_cache = false;
  app.add_flag("--no-archive-cache", no_archive_cache,
               "read and parse every ReadArchive again instead of replaying the archive parsed the first time");
  app.add_option("--procedural-path", o.procedural_paths,
                 "a folder Procedural \"RunProgram\" may start programs from (repeatable; also "
                 "$DARC_PROCEDURAL_PATH, colon-separated); the scene's Option \"searchpath\" \"procedural\" "
                 "may only narrow them")
      ->check(CLI::ExistingDirectory)
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--procedural-timeout", o.procedural_timeout_seconds,
                 "seconds a RunProgram generator may take for one request before it is killed (default 60)")
      ->check(CLI::Range(0.001, kMaxProceduralTimeoutSeconds));
  app.add_flag("--trust-rib", o.trust_rib,
               "I trust these RIB files: their Option \"searchpath\" \"procedural\" may add folders outside "
               "--procedural-path (each is reported), and their Display names may write outside the working "
               "folder (docs/threat-model.md)");
  std::string disk_reserve;
  app.add_option("--disk-reserve", disk_reserve,
                 "free space an image write must leave on its file system, e.g. 5G or 0 (default: 1 % of the "
                 "file system, at most 1G); a write that would leave less is refused");
  std::string memory_limit;
  app.add_option("--memory-limit", memory_limit,
                 "memory darc may use, e.g. 8G or 500M, or none (default: what the machine, the cgroup and "
                 "ulimit allow); a frame that would need more fails with an error instead of being killed");
  try {
    app.parse(argc, argv);
    o.archive_cache = !no_archive_cache;
    if (const char* env = std::getenv("DARC_PROCEDURAL_PATH")) o.procedural_env_paths = split_folder_list(env);
    if (memory_limit == "none") o.memory_limit_bytes = 0;
    else if (!memory_limit.empty()) {
      o.memory_limit_bytes = parse_byte_size(memory_limit);
      if (!o.memory_limit_bytes || *o.memory_limit_bytes == 0)
        throw CLI::ValidationError("--memory-limit", "expected a size such as 8G, 500M or 123456 (bytes), or none, "
                                                     "found \"" + memory_limit + "\"");
    }
    if (!disk_reserve.empty()) {
      o.disk_reserve_bytes = parse_byte_size(disk_reserve);
      if (!o.disk_reserve_bytes)
        throw CLI::ValidationError("--disk-reserve", "expected a size such as 5G, 500M, 123456 (bytes) or 0, found \"" +
                                                         disk_reserve + "\"");
    }
    if (!res.empty()) {
      if (!parse_resolution(res, o.xres, o.yres))
        throw CLI::ValidationError(
            "--res", "expected WxH with 1 <= W, H <= " + std::to_string(kMaxResolution) + ", found \"" + res + "\"");
    }
    if (!crop.empty()) {
      o.crop = parse_crop(crop);
      if (!o.crop) {
        std::ostringstream found;
        for (double v : crop) found << (found.tellp() > 0 ? " " : "") << v;
        throw CLI::ValidationError("--crop",
                                   "expected xmin xmax ymin ymax with 0 <= xmin < xmax <= 1 and 0 <= ymin "
                                   "< ymax <= 1, found \"" +
                                       found.str() + "\"");
      }
    }
    if (!frames.empty()) {
      std::string error;
      o.frames = FrameList::parse(frames, error);
      if (!o.frames) throw CLI::ValidationError("--frames", error);
    }
    o.hider = hider == "distance" ? HiderKind::Distance : HiderKind::Stochastic;
    if (contribution_threshold >= 0) o.contribution_threshold = contribution_threshold;
    o.area_light_cones = area_shadows == "cone";
  } catch (const CLI::ParseError& e) {
    exit_now = true;
    // CLI11 returns its own codes (100+) for usage errors; ours is 2 (libraries.md §6).
    int rc = app.exit(e);
    exit_code = rc == 0 ? kExitOk : kExitUsage;
  }
  return o;
}

}  // namespace darc
