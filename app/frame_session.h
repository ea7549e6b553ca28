// What becomes of each frame a SceneBuilder completes: its acceleration structure (kept from the
// previous frame when the geometry is the same), its render, its image and preview files (within
// the disk reserve, with --skip-existing), and its entry in the stats. The darc command
// (render_session.cpp) and the RI binding (ri/) both render through it, so that a scene given as
// RIB text or through the binding gives the same image.
#pragma once

#include "app/app_options.h"
#include "app/progress_reporter.h"
#include "core/scene/acceleration_reuse.h"
#include "core/scene/builder/scene_builder.h"
#include "integrator/color_config.h"
#include "parser/archive_cache.h"
#include "parser/diagnostics.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <set>
#include <string>

namespace darc {

class FrameSession {
 public:
  // `archives` (may be null) is the run's archive cache, whose counts go into the stats. Every
  // reference must outlive the session.
  FrameSession(const AppOptions& options, const ColorConfig& colors, Diagnostics& diag, ProgressReporter& progress,
               const ArchiveCache* archives);
  FrameSession(const FrameSession&) = delete;
  FrameSession& operator=(const FrameSession&) = delete;

  // The builder's callbacks: frames selected by --frames, each ready frame rendered and written.
  SceneBuilder::Callbacks callbacks();

  // After the last frame: writes the run's stats file (unless each frame wrote its own) and
  // returns whether every write succeeded.
  bool finish();
  // Frames --frames selected (rendered, skipped as existing, or failed).
  int frames_seen() const { return frames_seen_; }
  bool io_error() const { return io_error_; }

 private:
  using Clock = std::chrono::steady_clock;
  void frame_ready(Scene&& scene);
  nlohmann::json run_stats() const;

  const AppOptions& o_;
  const ColorConfig& colors_;
  Diagnostics& diag_;
  ProgressReporter& progress_;
  const ArchiveCache* archives_;
  nlohmann::json stats_frames_ = nlohmann::json::array();
  // "--stats stats/f.####.json": each frame's entry goes to a file of its own as soon as the frame
  // is written, so a sequence stopped part-way (a farm task cancelled) keeps the stats it made.
  bool stats_per_frame_;
  bool io_error_ = false;
  std::set<std::string> written_;
  Clock::time_point segment_start_ = Clock::now();
  AccelerationReuse acceleration_;  // a frame with the previous one's geometry keeps its BVH
  int frames_seen_ = 0;
};

}  // namespace darc
