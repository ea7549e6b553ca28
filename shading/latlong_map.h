// A latitude-longitude environment image as radiance over the sphere of directions, in RenderMan's
// dome convention (lookdev.md §2.2, derived from hdPrman's UsdLux-to-PxrDomeLight matrix): in the
// dome's own space +z is up and is the image's top row, t = acos(z) / pi down the rows and
// s = fract(-atan2(y, x) / (2 pi)) across (s = 0 at +x, 0.25 at -y, 0.5 at -x, 0.75 at +y).
// Radiance is constant over each texel, and the same texel values are what sampling draws from, so
// a sample's estimate L / pdf is exact for the map it lights with. Sampled by importance: texel
// (i, j) with weight luminance * sin(theta_j) (pbrt-v3 InfiniteAreaLight), p_omega = p(s, t) /
// (2 pi^2 sin theta).
#pragma once

#include "core/math/distribution_2d.h"
#include "core/math/vec.h"

#include <optional>
#include <string>
#include <vector>

namespace darc {

class LatLongMap {
 public:
  // The widest map kept: larger images are reduced (area filtered) to this width and half of it in
  // height, which keeps the distribution's build and its memory small for 8k HDRIs.
  static constexpr int kMaxWidth = 2048;

  // `texels` row by row from the top (t = 0), width x height, linear RGB radiance.
  LatLongMap(std::vector<Vec3f> texels, int width, int height);

  // Reads an image file (any OpenImageIO format; its first three channels, one channel as grey,
  // linear as stored). nullopt, with `reason`, when it cannot be read.
  static std::optional<LatLongMap> load(const std::string& path, std::string& reason);

  int width() const { return width_; }
  int height() const { return height_; }

  // The radiance seen looking along unit dome-space direction `d`.
  Vec3f radiance(const Vec3f& d) const;

  struct Sample {
    Vec3f direction;  // unit, dome space
    Vec3f radiance;
    float pdf = 0;  // per steradian
  };
  // A direction drawn by the map's importance from (u0, u1) in [0, 1)^2; false when it has no
  // density there (the poles).
  bool sample(float u0, float u1, Sample& out) const;
  // The density per steradian with which sample() draws `d`.
  float pdf(const Vec3f& d) const;

  // Dome-space direction <-> (s, t) of the convention above.
  static void to_st(const Vec3f& d, float& s, float& t);
  static Vec3f from_st(float s, float t);

 private:
  const Vec3f& texel(float s, float t) const;

  std::vector<Vec3f> texels_;
  int width_ = 0, height_ = 0;
  Distribution2D distribution_;
};

}  // namespace darc
