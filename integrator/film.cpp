#include "integrator/film.h"

#include <algorithm>
#include <cmath>

namespace darc {

namespace {

// A pixel whose net filter weight is below this fraction of its total absolute weight is
// dominated by cancelling negative lobes (catmull-rom, sinc with few samples): dividing by the
// net weight would amplify its colour by more than 1/fraction (20x), or by infinity at exactly 0.
// Such pixels use the plain mean of their samples instead.
constexpr float kMinNetWeightFraction = 0.05f;

// Samples that fall exactly on the support edge, or a hair inside it after rounding, must be
// judged by eval() alone; this margin (pixels) only widens the loop over candidate pixels.
constexpr int kSplatLoopMargin = 1;

float finite_or_zero(float v, bool& was_nonfinite) {
  if (std::isfinite(v)) return v;
  was_nonfinite = true;
  return 0.0f;
}

// Sums of huge (finite) inputs can still overflow to inf, and inf - inf to NaN.
float finite_or_zero(float v) { return std::isfinite(v) ? v : 0.0f; }

float sanitise_depth(float z) {
  if (!std::isfinite(z) || z > kNoHitDepth) return kNoHitDepth;
  return z;
}

// RI Exposure on one colour component. Negative input (from negative filter lobes) is clamped
// first: a fractional power of a negative number would be NaN.
float expose(float c, float gain, float inv_gamma) {
  const float v = std::max(c * gain, 0.0f);
  return inv_gamma == 1.0f ? v : std::pow(v, inv_gamma);
}

float positive_or_one(float v) { return std::isfinite(v) && v > 0.0f ? v : 1.0f; }

}  // namespace

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  PixelRect r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
  if (r.empty()) return PixelRect{r.x0, r.y0, r.x0, r.y0};
  return r;
}

int Image::channel_index(const std::string& name) const {
  for (int c = 0; c < channels(); ++c) {
    if (channel_names[c] == name) return c;
  }
  return -1;
}

float Image::at(int x, int y, int c) const {
  if (!data_window.contains(x, y) || c < 0 || c >= channels()) return 0.0f;
  const std::size_t index =
      (static_cast<std::size_t>(y - data_window.y0) * data_window.width() + (x - data_window.x0)) * channels() + c;
  return pixels[index];
}

// --- TileAccumulator ---

TileAccumulator::TileAccumulator(const PixelRect& tile, const PixelRect& covered, const PixelFilter& filter)
    : tile_(tile),
      covered_(covered),
      filter_(filter),
      sums_(static_cast<std::size_t>(covered.width()) * covered.height()) {}

TileAccumulator::PixelSums& TileAccumulator::sums_at(int x, int y) {
  return sums_[static_cast<std::size_t>(y - covered_.y0) * covered_.width() + (x - covered_.x0)];
}

void TileAccumulator::add_sample(float x, float y, const std::array<float, 4>& rgba, float z) {
  if (!std::isfinite(x) || !std::isfinite(y) || covered_.empty()) return;
  bool nonfinite = false;
  std::array<float, 4> c{};
  for (int k = 0; k < 4; ++k) c[k] = finite_or_zero(rgba[k], nonfinite);
  if (nonfinite) ++nonfinite_samples_;
  z = sanitise_depth(z);

  // Candidate pixels: centres i + 0.5 within the radius of x, clipped to what we cover.
  const float rx = filter_.radius_x();
  const float ry = filter_.radius_y();
  const int i0 = std::max(covered_.x0, static_cast<int>(std::floor(x - rx - 0.5f)) - kSplatLoopMargin);
  const int i1 = std::min(covered_.x1 - 1, static_cast<int>(std::floor(x + rx - 0.5f)) + kSplatLoopMargin);
  const int j0 = std::max(covered_.y0, static_cast<int>(std::floor(y - ry - 0.5f)) - kSplatLoopMargin);
  const int j1 = std::min(covered_.y1 - 1, static_cast<int>(std::floor(y + ry - 0.5f)) + kSplatLoopMargin);
  for (int j = j0; j <= j1; ++j) {
    const float dy = y - (static_cast<float>(j) + 0.5f);
    for (int i = i0; i <= i1; ++i) {
      const float dx = x - (static_cast<float>(i) + 0.5f);
      const float w = filter_.eval(dx, dy);
      if (w == 0.0f) continue;
      PixelSums& s = sums_at(i, j);
      for (int k = 0; k < 4; ++k) {
        s.weighted_rgba[k] += w * c[k];
        s.rgba[k] += c[k];
      }
      s.weight += w;
      s.abs_weight += std::fabs(w);
      s.count += 1.0f;
    }
  }
  // Depth belongs to the pixel whose square holds the sample, not to the filter footprint.
  const int px = static_cast<int>(std::floor(x));
  const int py = static_cast<int>(std::floor(y));
  if (covered_.contains(px, py)) {
    PixelSums& s = sums_at(px, py);
    s.z = std::min(s.z, z);
  }
}

// --- Film ---

Film::Film(int width, int height, PixelRect data_window, PixelFilter filter, int tile_size)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      data_window_(intersect(data_window, PixelRect{0, 0, width_, height_})),
      filter_(filter),
      tile_size_(tile_size > 0 ? tile_size : kDefaultTileSize),
      sums_(static_cast<std::size_t>(data_window_.width()) * data_window_.height()) {}

PixelRect Film::filter_reach(const PixelRect& r) const {
  // A sample in pixel column i lies in [i, i + 1] (a jittered position may round up to i + 1), so
  // it reaches the pixel centres within the radius: at most ceil(radius) columns beyond.
  const int ax = static_cast<int>(std::ceil(filter_.radius_x()));
  const int ay = static_cast<int>(std::ceil(filter_.radius_y()));
  return PixelRect{r.x0 - ax, r.y0 - ay, r.x1 + ax, r.y1 + ay};
}

std::vector<PixelRect> Film::tiles() const {
  if (data_window_.empty()) return {};
  const PixelRect sampled = intersect(filter_reach(data_window_), PixelRect{0, 0, width_, height_});
  std::vector<PixelRect> result;
  // The whole image's grid, from its corner whatever the crop, so that a crop's tiles are the
  // whole image's (cut), in the same order.
  for (int y = sampled.y0 / tile_size_ * tile_size_; y < sampled.y1; y += tile_size_) {
    for (int x = sampled.x0 / tile_size_ * tile_size_; x < sampled.x1; x += tile_size_) {
      const PixelRect tile = intersect(PixelRect{x, y, x + tile_size_, y + tile_size_}, sampled);
      if (!tile.empty()) result.push_back(tile);
    }
  }
  return result;
}

TileAccumulator Film::make_accumulator(const PixelRect& tile) const {
  return TileAccumulator(intersect(tile, data_window_), intersect(filter_reach(tile), data_window_), filter_);
}

void Film::merge(const TileAccumulator& tile) {
  const PixelRect& r = tile.covered_;
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const auto& src = tile.sums_[static_cast<std::size_t>(y - r.y0) * r.width() + (x - r.x0)];
      auto& dst = sums_[static_cast<std::size_t>(y - data_window_.y0) * data_window_.width() + (x - data_window_.x0)];
      for (int k = 0; k < 4; ++k) {
        dst.weighted_rgba[k] += src.weighted_rgba[k];
        dst.rgba[k] += src.rgba[k];
      }
      dst.weight += src.weight;
      dst.abs_weight += src.abs_weight;
      dst.count += src.count;
      dst.z = std::min(dst.z, src.z);
    }
  }
  nonfinite_samples_ += tile.nonfinite_samples_;
}

Image Film::resolve(float gain, float gamma) const {
  gain = positive_or_one(gain);
  const float inv_gamma = 1.0f / positive_or_one(gamma);
  Image image;
  image.width = width_;
  image.height = height_;
  image.data_window = data_window_;
  image.channel_names = {"R", "G", "B", "A", "Z"};
  const int nc = image.channels();
  image.pixels.resize(sums_.size() * nc);
  for (std::size_t p = 0; p < sums_.size(); ++p) {
    const auto& s = sums_[p];
    std::array<float, 4> rgba{};
    if (s.abs_weight > 0.0f && s.weight > kMinNetWeightFraction * s.abs_weight) {
      for (int k = 0; k < 4; ++k) rgba[k] = s.weighted_rgba[k] / s.weight;
    } else if (s.count > 0.0f) {
      for (int k = 0; k < 4; ++k) rgba[k] = s.rgba[k] / s.count;
    }
    float* out = &image.pixels[p * nc];
    // Negative filter lobes can push a pixel slightly below 0 near edges (ringing). Negative
    // light or coverage means nothing downstream, so RGB and A are clamped to >= 0; nothing else
    // is clamped, since scene-linear values above 1 are legitimate.
    for (int k = 0; k < 3; ++k) out[k] = finite_or_zero(expose(rgba[k], gain, inv_gamma));
    out[3] = finite_or_zero(std::max(rgba[3], 0.0f));
    out[4] = s.z;
  }
  return image;
}

}  // namespace darc
