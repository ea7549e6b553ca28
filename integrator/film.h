// The film: filtered reconstruction of pixel values from samples, tile by tile, deterministic
// for any thread count.
//
// Rendering is tiled: each tile is rendered by one thread into its own TileAccumulator, and the
// accumulators are merged into the Film in tile-index order (not completion order), so every
// floating-point sum happens in the same order whatever the number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "integrator/pixel_filter.h"

namespace darc {

// A half-open rectangle of raster pixels [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  int width() const { return x1 > x0 ? x1 - x0 : 0; }
  int height() const { return y1 > y0 ? y1 - y0 : 0; }
  bool empty() const { return width() == 0 || height() == 0; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  bool operator==(const PixelRect&) const = default;
};

PixelRect intersect(const PixelRect& a, const PixelRect& b);

// Depth recorded for a pixel that no sample hit, and the cap for any depth given to the film:
// RI_INFINITY (ri.h), finite so that it survives every file format and never becomes NaN.
inline constexpr float kNoHitDepth = 1.0e38f;

// Side of the square render tiles, in pixels: small enough to balance 2-16 threads on typical
// frames, large enough that the filter apron (radius pixels each side) stays a small overhead.
inline constexpr int kDefaultTileSize = 32;

// A float image over a data window, channels interleaved, rows top to bottom (raster y down).
// The display window is [0, width) x [0, height); pixels holds only the data window.
struct Image {
  int width = 0, height = 0;               // display (full) resolution
  PixelRect data_window;                   // where pixels are defined (the CropWindow rectangle)
  std::vector<std::string> channel_names;  // e.g. "R", "G", "B", "A", "Z"
  std::vector<float> pixels;               // data_window.width() * data_window.height() * channels()

  int channels() const { return static_cast<int>(channel_names.size()); }
  // Index of a channel by name, or -1.
  int channel_index(const std::string& name) const;
  // Value at raster pixel (x, y) of channel c; 0 outside the data window.
  float at(int x, int y, int c) const;
};

class Film;

// The per-tile sample sums of one render tile, over the tile expanded by the filter radius (so
// samples near the tile edge can splat into neighbouring tiles' pixels), clipped to the data
// window. Owned by the one thread rendering the tile.
class TileAccumulator {
 public:
  // A sample at continuous raster position (x, y) (pixel (i, j) spans [i, i+1) x [j, j+1), centre
  // i + 0.5) with premultiplied linear rgba and camera depth z. It is splatted with filter
  // weights into every covered pixel whose centre is within the filter support. Non-finite rgba
  // components count as 0 (and are counted); non-finite or huge z counts as kNoHitDepth.
  void add_sample(float x, float y, const std::array<float, 4>& rgba, float z);

  const PixelRect& tile() const { return tile_; }
  const PixelRect& covered() const { return covered_; }
  // Number of samples that arrived with a NaN or infinite colour component.
  std::int64_t nonfinite_samples() const { return nonfinite_samples_; }

 private:
  friend class Film;
  // Sums for one pixel. The unweighted sums are the fallback when the filter weights cancel.
  struct PixelSums {
    std::array<float, 4> weighted_rgba{};
    float weight = 0.0f;
    float abs_weight = 0.0f;
    std::array<float, 4> rgba{};
    float count = 0.0f;
    float z = kNoHitDepth;
  };

  TileAccumulator(const PixelRect& tile, const PixelRect& covered, const PixelFilter& filter);
  PixelSums& sums_at(int x, int y);

  PixelRect tile_;
  PixelRect covered_;
  PixelFilter filter_;
  std::vector<PixelSums> sums_;
  std::int64_t nonfinite_samples_ = 0;
};

class Film {
 public:
  // A width x height image of which data_window (clipped to the image) is rendered; the
  // data window is the CropWindow rectangle in raster pixels. tile_size <= 0 means the default.
  Film(int width, int height, PixelRect data_window, PixelFilter filter, int tile_size = kDefaultTileSize);

  int width() const { return width_; }
  int height() const { return height_; }
  const PixelRect& data_window() const { return data_window_; }
  const PixelFilter& filter() const { return filter_; }

  // The render tiles: the pixels whose samples are rendered, one rectangle per tile, in merge
  // order (the index in this vector). They are the whole image's tile_size x tile_size grid from
  // its top-left corner, row-major, cut to the data window grown by the filter's reach (the
  // pixels whose samples reach a pixel of it) and to the image. So a crop renders the samples
  // around it that its edge pixels' filters reach, and each of its pixels gets the same samples
  // added in the same order as in the whole image: a crop is bitwise that part of the whole image
  // (tests/render/crop_render_test.cpp), which lets a farm render a frame as tiles (darc --crop).
  std::vector<PixelRect> tiles() const;
  // An empty accumulator for a tile from tiles(), covering the tile grown by the filter's reach.
  TileAccumulator make_accumulator(const PixelRect& tile) const;
  // Adds a tile's sums into the film. Call it in tile-index order for bitwise determinism.
  void merge(const TileAccumulator& tile);

  // Final pixels over the data window: channels R, G, B, A (premultiplied), Z.
  // Colour = weighted sum / weight sum; Z = nearest depth among samples inside the pixel square
  // (kNoHitDepth if none). RI Exposure is applied to RGB as (c * gain)^(1 / gamma); gain or
  // gamma that are not finite and positive mean 1.
  Image resolve(float gain = 1.0f, float gamma = 1.0f) const;

  std::int64_t nonfinite_samples() const { return nonfinite_samples_; }

 private:
  // `r` grown by the filter's reach: ceil(radius) pixels each side.
  PixelRect filter_reach(const PixelRect& r) const;

  int width_, height_;
  PixelRect data_window_;
  PixelFilter filter_;
  int tile_size_;
  std::vector<TileAccumulator::PixelSums> sums_;  // over the data window
  std::int64_t nonfinite_samples_ = 0;
};

}  // namespace darc
