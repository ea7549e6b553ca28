#include "integrator/film.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <thread>
#include <vector>

namespace darc {
namespace {

struct Sample {
  float x, y;
  std::array<float, 4> rgba;
  float z;
};

// Deterministic samples for one tile: a pure function of the pixel, like the renderer's RNG.
std::vector<Sample> samples_for_tile(const PixelRect& tile, int per_pixel) {
  std::vector<Sample> out;
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x) {
      std::mt19937 rng(static_cast<std::uint32_t>(y * 10007 + x));
      std::uniform_real_distribution<float> u(0.0f, 1.0f);
      for (int s = 0; s < per_pixel; ++s) {
        out.push_back({x + u(rng), y + u(rng), {u(rng), u(rng), u(rng), u(rng)}, 1.0f + 10.0f * u(rng)});
      }
    }
  }
  return out;
}

TileAccumulator render_tile(const Film& film, const PixelRect& tile, int per_pixel) {
  TileAccumulator acc = film.make_accumulator(tile);
  for (const Sample& s : samples_for_tile(tile, per_pixel)) acc.add_sample(s.x, s.y, s.rgba, s.z);
  return acc;
}

Image render(Film film, int per_pixel) {
  for (const PixelRect& tile : film.tiles()) film.merge(render_tile(film, tile, per_pixel));
  return film.resolve();
}

PixelFilter filter(const char* name, float w) { return make_pixel_filter(name, w, w).value(); }

TEST(Film, TilesAreTheImagesGridRowMajor) {
  const Film film(100, 50, PixelRect{0, 0, 100, 50}, filter("gaussian", 2), 32);
  const auto tiles = film.tiles();
  ASSERT_EQ(tiles.size(), 8u);  // 4 columns (32, 32, 32, 4) x 2 rows (32, 18)
  EXPECT_EQ(tiles[0], (PixelRect{0, 0, 32, 32}));
  EXPECT_EQ(tiles[3], (PixelRect{96, 0, 100, 32}));
  EXPECT_EQ(tiles[4], (PixelRect{0, 32, 32, 50}));
}

TEST(Film, ACropsTilesAreTheImagesGridCutToTheCropAndTheFilterReachAroundIt) {
  // The gaussian 3 3 reaches ceil(1.5) = 2 pixels: samples of columns 8 to 81, rows 3 to 46.
  const Film film(100, 50, PixelRect{10, 5, 80, 45}, filter("gaussian", 3), 32);
  const auto tiles = film.tiles();
  ASSERT_EQ(tiles.size(), 6u);  // the image's columns 0, 32, 64 x rows 0, 32, cut
  EXPECT_EQ(tiles[0], (PixelRect{8, 3, 32, 32}));
  EXPECT_EQ(tiles[1], (PixelRect{32, 3, 64, 32}));
  EXPECT_EQ(tiles[2], (PixelRect{64, 3, 82, 32}));
  EXPECT_EQ(tiles[3], (PixelRect{8, 32, 32, 47}));
  EXPECT_EQ(tiles[5], (PixelRect{64, 32, 82, 47}));
  // At the image's edge nothing is sampled outside it; a crop within one grid tile is one tile.
  const Film edge(100, 50, PixelRect{0, 40, 20, 50}, filter("gaussian", 3), 32);
  EXPECT_EQ(edge.tiles(), (std::vector<PixelRect>{PixelRect{0, 38, 22, 50}}));
}

// With samples a pure function of their pixel (as the hiders draw them), a crop's pixels are
// bitwise the whole film's there, for a filter reaching 2 pixels with negative lobes.
TEST(Film, ACropsPixelsAreBitwiseTheWholeFilmsPixels) {
  const int w = 70, h = 45;
  const Image whole = render(Film(w, h, PixelRect{0, 0, w, h}, filter("catmull-rom", 4), 16), 3);
  for (const PixelRect crop : {PixelRect{5, 7, 37, 30}, PixelRect{16, 0, 32, 16}, PixelRect{50, 40, 70, 45}}) {
    const Image part = render(Film(w, h, crop, filter("catmull-rom", 4), 16), 3);
    ASSERT_EQ(part.data_window, crop);
    for (int y = crop.y0; y < crop.y1; ++y)
      for (int x = crop.x0; x < crop.x1; ++x)
        for (int c = 0; c < part.channels(); ++c) {
          const float a = part.at(x, y, c), b = whole.at(x, y, c);
          ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << x << "," << y << " channel " << c;
        }
  }
}

TEST(Film, DataWindowIsClippedToTheImage) {
  const Film film(16, 8, PixelRect{-4, 2, 40, 6}, filter("box", 1));
  EXPECT_EQ(film.data_window(), (PixelRect{0, 2, 16, 6}));
}

TEST(Film, AccumulatorCoversTileExpandedByFilterRadius) {
  const Film film(64, 64, PixelRect{0, 0, 64, 64}, filter("gaussian", 3), 16);
  const TileAccumulator acc = film.make_accumulator(PixelRect{16, 0, 32, 16});
  EXPECT_EQ(acc.covered(), (PixelRect{14, 0, 34, 18}));  // ceil(1.5) = 2, clipped at the top
}

TEST(Film, BoxOneByOneReproducesPerPixelMeansExactly) {
  const int w = 10, h = 7, spp = 5;
  Film film(w, h, PixelRect{0, 0, w, h}, filter("box", 1), 4);
  const Image image = render(film, spp);
  ASSERT_EQ(image.channel_names, (std::vector<std::string>{"R", "G", "B", "A", "Z"}));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto samples = samples_for_tile(PixelRect{x, y, x + 1, y + 1}, spp);
      std::array<float, 4> sum{};
      float zmin = std::numeric_limits<float>::max();
      for (const auto& s : samples) {
        for (int k = 0; k < 4; ++k) sum[k] += s.rgba[k];
        zmin = std::min(zmin, s.z);
      }
      for (int k = 0; k < 4; ++k) EXPECT_EQ(image.at(x, y, k), sum[k] / static_cast<float>(spp)) << x << "," << y;
      EXPECT_EQ(image.at(x, y, 4), zmin);
    }
  }
}

TEST(Film, ConstantImageStaysConstantForEveryFilter) {
  const char* names[] = {"box", "triangle", "gaussian", "catmull-rom", "sinc"};
  const std::array<float, 4> grey{0.3f, 0.5f, 2.0f, 1.0f};
  for (const char* name : names) {
    for (float width : {2.0f, 3.0f, 4.0f}) {
      Film film(12, 9, PixelRect{0, 0, 12, 9}, filter(name, width), 5);
      for (const PixelRect& tile : film.tiles()) {
        TileAccumulator acc = film.make_accumulator(tile);
        for (const Sample& s : samples_for_tile(tile, 4)) acc.add_sample(s.x, s.y, grey, s.z);
        film.merge(acc);
      }
      const Image image = film.resolve();
      for (int y = 0; y < 9; ++y) {
        for (int x = 0; x < 12; ++x) {
          for (int k = 0; k < 4; ++k) {
            EXPECT_NEAR(image.at(x, y, k), grey[k], 1e-5f * grey[k]) << name << " " << width << " " << x << "," << y;
          }
        }
      }
    }
  }
}

TEST(Film, MergingInTileOrderIsBitwiseDeterministicWhateverTheThreadOrder) {
  const Film film(70, 45, PixelRect{0, 0, 70, 45}, filter("catmull-rom", 4), 16);
  const auto tiles = film.tiles();

  Film serial = film;
  for (const auto& tile : tiles) serial.merge(render_tile(film, tile, 3));
  const Image reference = serial.resolve();

  // Render the tiles out of order on three threads, then merge in tile order.
  std::vector<std::optional<TileAccumulator>> done(tiles.size());
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t) {
    threads.emplace_back([&, t] {
      for (int i = static_cast<int>(tiles.size()) - 1 - t; i >= 0; i -= 3) done[i] = render_tile(film, tiles[i], 3);
    });
  }
  for (auto& th : threads) th.join();
  Film parallel = film;
  for (const auto& acc : done) parallel.merge(*acc);
  const Image image = parallel.resolve();

  ASSERT_EQ(image.pixels.size(), reference.pixels.size());
  EXPECT_EQ(std::memcmp(image.pixels.data(), reference.pixels.data(), image.pixels.size() * sizeof(float)), 0);
}

TEST(Film, DifferentTilingsGiveBitwiseIdenticalImagesWithoutFilterOverlap) {
  const Image a = render(Film(37, 21, PixelRect{0, 0, 37, 21}, filter("box", 1), 3), 4);
  const Image b = render(Film(37, 21, PixelRect{0, 0, 37, 21}, filter("box", 1), 16), 4);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
}

TEST(Film, PixelWithoutWeightIsZeroNotNan) {
  Film film(8, 8, PixelRect{0, 0, 8, 8}, filter("catmull-rom", 4), 8);
  TileAccumulator acc = film.make_accumulator(film.tiles()[0]);
  // One sample exactly one pixel right of pixel (2, 2)'s centre: the interpolating kernel gives
  // that pixel weight exactly 0, and pixels far away get no sample at all.
  acc.add_sample(3.5f, 2.5f, {1, 1, 1, 1}, 5.0f);
  film.merge(acc);
  const Image image = film.resolve();
  for (float v : image.pixels) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(image.at(2, 2, 0), 0.0f);
  EXPECT_EQ(image.at(7, 7, 0), 0.0f);
  EXPECT_EQ(image.at(7, 7, 4), kNoHitDepth);
  EXPECT_FLOAT_EQ(image.at(3, 2, 0), 1.0f);
  EXPECT_EQ(image.at(3, 2, 4), 5.0f);
}

TEST(Film, PixelReachedOnlyByNegativeLobesIsFiniteAndNonNegative) {
  Film film(8, 8, PixelRect{0, 0, 8, 8}, filter("catmull-rom", 4), 8);
  TileAccumulator acc = film.make_accumulator(film.tiles()[0]);
  acc.add_sample(4.0f, 2.5f, {0.5f, 0.25f, 1.0f, 1.0f}, 1.0f);  // pixel (2, 2) sees only dx = 1.5
  film.merge(acc);
  const Image image = film.resolve();
  const float r = image.at(2, 2, 0);
  EXPECT_TRUE(std::isfinite(r));
  EXPECT_GE(r, 0.0f);
  EXPECT_LE(r, 0.5f);
}

TEST(Film, NegativeLobesNeverGiveNegativeValues) {
  Film film(16, 4, PixelRect{0, 0, 16, 4}, filter("sinc", 6), 8);
  for (const auto& tile : film.tiles()) {
    TileAccumulator acc = film.make_accumulator(tile);
    for (const Sample& s : samples_for_tile(tile, 4)) {
      const float v = s.x < 8.0f ? 0.0f : 10.0f;  // a hard edge rings on both sides
      acc.add_sample(s.x, s.y, {v, v, v, 1.0f}, s.z);
    }
    film.merge(acc);
  }
  const Image image = film.resolve();
  for (float v : image.pixels) EXPECT_GE(v, 0.0f);
}

TEST(Film, NonFiniteSamplesAreCountedAndNeverReachPixels) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  Film film(4, 4, PixelRect{0, 0, 4, 4}, filter("gaussian", 2), 4);
  TileAccumulator acc = film.make_accumulator(film.tiles()[0]);
  acc.add_sample(1.5f, 1.5f, {nan, 1, 1, 1}, nan);
  acc.add_sample(2.5f, 1.5f, {inf, -inf, 1, 1}, inf);
  acc.add_sample(nan, 1.5f, {1, 1, 1, 1}, 1);
  acc.add_sample(1.2f, 2.7f, {3e38f, 3e38f, 3e38f, 1}, 1);  // sums overflow to inf
  acc.add_sample(1.3f, 2.6f, {3e38f, 3e38f, 3e38f, 1}, 1);
  EXPECT_EQ(acc.nonfinite_samples(), 2);
  film.merge(acc);
  EXPECT_EQ(film.nonfinite_samples(), 2);
  const Image image = film.resolve();
  for (float v : image.pixels) EXPECT_TRUE(std::isfinite(v));
}

TEST(Film, SamplesOutsideTheCropWindowAreIgnored) {
  Film film(10, 10, PixelRect{2, 3, 6, 8}, filter("box", 1), 32);
  ASSERT_EQ(film.tiles().size(), 1u);
  TileAccumulator acc = film.make_accumulator(film.tiles()[0]);
  acc.add_sample(0.5f, 0.5f, {1, 1, 1, 1}, 1);  // outside the crop: dropped
  acc.add_sample(2.5f, 3.5f, {0.5f, 0.5f, 0.5f, 1}, 1);
  film.merge(acc);
  const Image image = film.resolve();
  EXPECT_EQ(image.data_window, (PixelRect{2, 3, 6, 8}));
  EXPECT_EQ(image.pixels.size(), 4u * 5u * 5u);
  EXPECT_EQ(image.at(0, 0, 0), 0.0f);
  EXPECT_EQ(image.at(2, 3, 0), 0.5f);
}

TEST(Film, ExposureIsGainThenInverseGamma) {
  Film film(2, 2, PixelRect{0, 0, 2, 2}, filter("box", 1), 2);
  TileAccumulator acc = film.make_accumulator(film.tiles()[0]);
  acc.add_sample(0.5f, 0.5f, {0.25f, 0.125f, 0.0f, 0.5f}, 1);
  film.merge(acc);
  const Image image = film.resolve(2.0f, 2.0f);
  EXPECT_FLOAT_EQ(image.at(0, 0, 0), std::sqrt(0.5f));
  EXPECT_FLOAT_EQ(image.at(0, 0, 1), 0.5f);
  EXPECT_EQ(image.at(0, 0, 2), 0.0f);
  EXPECT_EQ(image.at(0, 0, 3), 0.5f);                                              // alpha is not exposed
  const Image bad = film.resolve(std::numeric_limits<float>::quiet_NaN(), -1.0f);  // means 1 1
  EXPECT_EQ(bad.at(0, 0, 0), 0.25f);
}

}  // namespace
}  // namespace darc
