#include "bench/log_log_plot.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <system_error>

namespace darc::bench {

namespace {

// Canvas layout in pixels: the plot area, with margins for tick labels and a legend column.
constexpr int kWidth = 1180;
constexpr int kHeight = 720;
constexpr int kMarginLeft = 90;
constexpr int kMarginTop = 60;
constexpr int kLegendWidth = 330;
constexpr int kMarginBottom = 70;
constexpr int kFontSize = 16;
constexpr int kTitleFontSize = 20;
constexpr int kMarkerHalfSize = 4;
constexpr int kDashOn = 10, kDashOff = 6;  // dash pattern of the distance hider's lines, pixels
constexpr int kLegendRowHeight = 24;
// Padding around the data, as a fraction of the data's span in decades (and at least this many
// decades), so that no point sits on the frame.
constexpr double kPadFraction = 0.08;
constexpr double kMinPadDecades = 0.1;

// Display-referred colours, written to the 8-bit file as they are.
constexpr std::array<float, 3> kBackground{1, 1, 1};
constexpr std::array<float, 3> kFrame{0.15f, 0.15f, 0.15f};
constexpr std::array<float, 3> kMajorGrid{0.78f, 0.78f, 0.78f};
constexpr std::array<float, 3> kMinorGrid{0.92f, 0.92f, 0.92f};
constexpr std::array<float, 3> kText{0.1f, 0.1f, 0.1f};

struct LogRange {
  double lo = 0, hi = 1;  // log10 of the axis ends
};

LogRange padded_range(double min_value, double max_value) {
  double lo = std::log10(min_value), hi = std::log10(max_value);
  double pad = std::max(kMinPadDecades, kPadFraction * (hi - lo));
  return {lo - pad, hi + pad};
}

// "0.01", "1", "100", or "1e-05" outside [1e-3, 1e3]: what a reader expects on a log axis.
std::string tick_label(double value) {
  char buf[32];
  double e = std::log10(value);
  if (e >= -3.5 && e <= 3.5)
    std::snprintf(buf, sizeof buf, "%g", value);
  else
    std::snprintf(buf, sizeof buf, "%.0e", value);
  return buf;
}

class Canvas {
 public:
  Canvas() : buf_(OIIO::ImageSpec(kWidth, kHeight, 3, OIIO::TypeDesc::FLOAT)) {
    OIIO::ImageBufAlgo::fill(buf_, kBackground);
    for (const char* name : {"DejaVuSans", "DejaVu Sans", ""}) {
      if (OIIO::ImageBufAlgo::text_size("0", kFontSize, name).defined()) {
        font_ = name;
        has_font_ = true;
        break;
      }
    }
  }

  bool has_font() const { return has_font_; }
  OIIO::ImageBuf& buf() { return buf_; }

  void line(int x0, int y0, int x1, int y1, const std::array<float, 3>& c, int thickness = 1) {
    for (int k = 0; k < thickness; ++k) {
      bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);  // thicken across the line's direction
      int dx = steep ? k : 0, dy = steep ? 0 : k;
      OIIO::ImageBufAlgo::render_line(buf_, x0 + dx, y0 + dy, x1 + dx, y1 + dy, c);
    }
  }

  void dashed_line(int x0, int y0, int x1, int y1, const std::array<float, 3>& c, int thickness) {
    double length = std::hypot(double(x1 - x0), double(y1 - y0));
    if (length < 1) return;
    for (double s = 0; s < length; s += kDashOn + kDashOff) {
      double e = std::min(length, s + kDashOn);
      line(int(std::lround(x0 + (x1 - x0) * s / length)), int(std::lround(y0 + (y1 - y0) * s / length)),
           int(std::lround(x0 + (x1 - x0) * e / length)), int(std::lround(y0 + (y1 - y0) * e / length)), c, thickness);
    }
  }

  void marker(int x, int y, const std::array<float, 3>& c, bool hollow) {
    int h = kMarkerHalfSize;
    if (hollow) {
      OIIO::ImageBufAlgo::render_box(buf_, x - h, y - h, x + h, y + h, kBackground, true);
      OIIO::ImageBufAlgo::render_box(buf_, x - h, y - h, x + h, y + h, c, false);
      OIIO::ImageBufAlgo::render_box(buf_, x - h + 1, y - h + 1, x + h - 1, y + h - 1, c, false);
    } else {
      OIIO::ImageBufAlgo::render_box(buf_, x - h, y - h, x + h, y + h, c, true);
    }
  }

  void text(int x, int y, const std::string& s, OIIO::ImageBufAlgo::TextAlignX ax,
            OIIO::ImageBufAlgo::TextAlignY ay, int size = kFontSize) {
    if (has_font_) OIIO::ImageBufAlgo::render_text(buf_, x, y, s, size, font_, kText, ax, ay);
  }

 private:
  OIIO::ImageBuf buf_;
  std::string font_;
  bool has_font_ = false;
};

struct Frame {
  int left = kMarginLeft, top = kMarginTop, right = kWidth - kLegendWidth, bottom = kHeight - kMarginBottom;
  LogRange x, y;
  int px(double v) const { return left + int(std::lround((std::log10(v) - x.lo) / (x.hi - x.lo) * (right - left))); }
  int py(double v) const { return bottom - int(std::lround((std::log10(v) - y.lo) / (y.hi - y.lo) * (bottom - top))); }
};

// Grid lines at 1..9 times each decade; labels at decades, and at 2 and 5 too when the axis
// spans fewer than two decades (else it could have a single label).
template <typename Draw>
void for_each_tick(const LogRange& r, Draw draw) {
  int first = int(std::floor(r.lo)), last = int(std::ceil(r.hi));
  bool few_decades = (std::floor(r.hi) - std::ceil(r.lo)) < 1;
  for (int e = first; e <= last; ++e) {
    for (int m = 1; m <= 9; ++m) {
      double v = m * std::pow(10.0, e);
      double lv = std::log10(v);
      if (lv < r.lo || lv > r.hi) continue;
      draw(v, m == 1, m == 1 || (few_decades && (m == 2 || m == 5)));
    }
  }
}

void draw_axes(Canvas& c, const Frame& f, const PlotText& text) {
  using AX = OIIO::ImageBufAlgo::TextAlignX;
  using AY = OIIO::ImageBufAlgo::TextAlignY;
  for_each_tick(f.x, [&](double v, bool major, bool labelled) {
    int x = f.px(v);
    c.line(x, f.top, x, f.bottom, major ? kMajorGrid : kMinorGrid);
    if (labelled) c.text(x, f.bottom + 8, tick_label(v), AX::Center, AY::Top);
  });
  for_each_tick(f.y, [&](double v, bool major, bool labelled) {
    int y = f.py(v);
    c.line(f.left, y, f.right, y, major ? kMajorGrid : kMinorGrid);
    if (labelled) c.text(f.left - 8, y, tick_label(v), AX::Right, AY::Center);
  });
  OIIO::ImageBufAlgo::render_box(c.buf(), f.left, f.top, f.right, f.bottom, kFrame, false);
  c.text((f.left + f.right) / 2, f.bottom + 40, text.x_label, AX::Center, AY::Top);
  c.text(f.left, f.top - 10, text.y_label, AX::Center, AY::Bottom);
  c.text(kWidth / 2, 8, text.title, AX::Center, AY::Top, kTitleFontSize);
}

void draw_series(Canvas& c, const Frame& f, const PlotSeries& s) {
  constexpr int kLineThickness = 2;
  int prev_x = 0, prev_y = 0;
  bool has_prev = false;
  for (const SpeedErrorPoint& p : s.points) {
    if (!(p.seconds > 0 && p.rmse > 0)) continue;
    int x = f.px(p.seconds), y = f.py(p.rmse);
    if (has_prev) {
      if (s.dashed)
        c.dashed_line(prev_x, prev_y, x, y, s.color, kLineThickness);
      else
        c.line(prev_x, prev_y, x, y, s.color, kLineThickness);
    }
    prev_x = x, prev_y = y, has_prev = true;
  }
  for (const SpeedErrorPoint& p : s.points)
    if (p.seconds > 0 && p.rmse > 0) c.marker(f.px(p.seconds), f.py(p.rmse), s.color, s.dashed);
}

void draw_legend(Canvas& c, const Frame& f, std::span<const PlotSeries> series) {
  constexpr int kSwatchLength = 36;
  int x = f.right + 20, y = f.top + 10;
  for (const PlotSeries& s : series) {
    if (s.dashed)
      c.dashed_line(x, y, x + kSwatchLength, y, s.color, 2);
    else
      c.line(x, y, x + kSwatchLength, y, s.color, 2);
    c.marker(x + kSwatchLength / 2, y, s.color, s.dashed);
    c.text(x + kSwatchLength + 10, y, s.label, OIIO::ImageBufAlgo::TextAlignX::Left,
           OIIO::ImageBufAlgo::TextAlignY::Center);
    y += kLegendRowHeight;
  }
}

}  // namespace

PlotResult write_log_log_plot(const std::string& path, std::span<const PlotSeries> series, const PlotText& text) {
  double x_min = std::numeric_limits<double>::infinity(), x_max = 0;
  double y_min = std::numeric_limits<double>::infinity(), y_max = 0;
  for (const PlotSeries& s : series) {
    for (const SpeedErrorPoint& p : s.points) {
      if (!(p.seconds > 0 && p.rmse > 0 && std::isfinite(p.seconds) && std::isfinite(p.rmse))) continue;
      x_min = std::min(x_min, p.seconds), x_max = std::max(x_max, p.seconds);
      y_min = std::min(y_min, p.rmse), y_max = std::max(y_max, p.rmse);
    }
  }
  if (!(x_max > 0 && y_max > 0)) return {false, "no point with a positive time and RMSE to plot", false};

  Canvas canvas;
  Frame frame;
  frame.x = padded_range(x_min, x_max);
  frame.y = padded_range(y_min, y_max);
  draw_axes(canvas, frame, text);
  for (const PlotSeries& s : series) draw_series(canvas, frame, s);
  draw_legend(canvas, frame, series);

  // Write beside the target with the same extension (OIIO picks the format from it), then rename.
  std::filesystem::path target(path);
  std::filesystem::path temp = target;
  temp.replace_filename(target.stem().string() + ".tmp" + target.extension().string());
  if (!canvas.buf().write(temp.string(), OIIO::TypeDesc::UINT8))
    return {false, "cannot write " + temp.string() + ": " + canvas.buf().geterror(), canvas.has_font()};
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) return {false, "cannot rename " + temp.string() + " to " + path + ": " + ec.message(), canvas.has_font()};
  return {true, "", canvas.has_font()};
}

}  // namespace darc::bench
