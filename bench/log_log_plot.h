// A small log-log line plot drawn with OpenImageIO's ImageBufAlgo::render_line / render_box /
// render_text, for the speed-against-error report (time on x, RMSE on y). No plotting library:
// the report must build from the Debian packages the renderer already needs.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "bench/equal_error.h"

namespace darc::bench {

struct PlotSeries {
  std::string label;                  // legend text
  std::array<float, 3> color{0, 0, 0};  // linear RGB in [0, 1]
  bool dashed = false;                // dashed line and hollow markers (the distance hider)
  std::vector<SpeedErrorPoint> points;  // x = seconds, y = rmse; non-positive values are skipped
};

struct PlotText {
  std::string title;
  std::string x_label = "render time (s)";
  std::string y_label = "RMSE";
};

struct PlotResult {
  bool ok = false;
  std::string error;        // when !ok
  bool text_drawn = false;  // false when OpenImageIO found no font: the plot has no labels
};

// Draws every series on decade-gridded log axes spanning all points and writes the image to
// `path` (the format from its extension, e.g. .png), atomically (temporary name, then rename).
PlotResult write_log_log_plot(const std::string& path, std::span<const PlotSeries> series, const PlotText& text);

}  // namespace darc::bench
