#include "shading/latlong_map.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darc {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float luminance(const Vec3f& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// Non-finite or negative texels (an HDRI's NaNs) would poison every estimate: black instead.
Vec3f sane(Vec3f c) {
  auto fix = [](float v) { return std::isfinite(v) && v > 0 ? v : 0.0f; };
  return {fix(c.x), fix(c.y), fix(c.z)};
}

}  // namespace

LatLongMap::LatLongMap(std::vector<Vec3f> texels, int width, int height)
    : texels_(std::move(texels)), width_(std::max(width, 1)), height_(std::max(height, 1)) {
  texels_.resize(size_t(width_) * size_t(height_));
  std::vector<float> weights(texels_.size());
  for (int j = 0; j < height_; ++j) {
    const float sin_theta = std::sin(kPi * (float(j) + 0.5f) / float(height_));
    for (int i = 0; i < width_; ++i) {
      Vec3f& c = texels_[size_t(j) * size_t(width_) + size_t(i)];
      c = sane(c);
      weights[size_t(j) * size_t(width_) + size_t(i)] = luminance(c) * sin_theta;
    }
  }
  distribution_ = Distribution2D(weights, width_, height_);
}

std::optional<LatLongMap> LatLongMap::load(const std::string& path, std::string& reason) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    reason = OIIO::geterror();
    if (reason.empty()) reason = "cannot be read as an image";
    return std::nullopt;
  }
  const OIIO::ImageSpec spec = in->spec();
  const int w = spec.width, h = spec.height, nc = spec.nchannels;
  if (w <= 0 || h <= 0 || nc <= 0) {
    reason = "the image is empty";
    return std::nullopt;
  }
  std::vector<float> pixels(size_t(w) * size_t(h) * size_t(nc));
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, pixels.data())) {
    reason = in->geterror();
    if (reason.empty()) reason = "its pixels cannot be read";
    return std::nullopt;
  }
  // Reduced by an integer factor, averaging factor x factor blocks (the area filter), until it
  // is no wider than kMaxWidth.
  const int factor = (w + kMaxWidth - 1) / kMaxWidth;
  const int ow = std::max(1, w / factor), oh = std::max(1, h / factor);
  std::vector<Vec3f> texels(size_t(ow) * size_t(oh));
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      Vec3f sum{};
      int count = 0;
      for (int dy = 0; dy < factor && y * factor + dy < h; ++dy)
        for (int dx = 0; dx < factor && x * factor + dx < w; ++dx) {
          const float* p = &pixels[(size_t(y * factor + dy) * size_t(w) + size_t(x * factor + dx)) * size_t(nc)];
          sum += sane(nc >= 3 ? Vec3f{p[0], p[1], p[2]} : Vec3f{p[0], p[0], p[0]});
          ++count;
        }
      texels[size_t(y) * size_t(ow) + size_t(x)] = sum / float(std::max(count, 1));
    }
  return LatLongMap(std::move(texels), ow, oh);
}

void LatLongMap::to_st(const Vec3f& d, float& s, float& t) {
  t = std::acos(std::clamp(d.z, -1.0f, 1.0f)) / kPi;
  s = -std::atan2(d.y, d.x) / (2 * kPi);
  s -= std::floor(s);
  if (!(s < 1.0f)) s = 0.0f;
}

Vec3f LatLongMap::from_st(float s, float t) {
  const float theta = kPi * t, phi = -2 * kPi * s;
  const float sin_theta = std::sin(theta);
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), std::cos(theta)};
}

const Vec3f& LatLongMap::texel(float s, float t) const {
  const int i = std::clamp(int(s * float(width_)), 0, width_ - 1);
  const int j = std::clamp(int(t * float(height_)), 0, height_ - 1);
  return texels_[size_t(j) * size_t(width_) + size_t(i)];
}

Vec3f LatLongMap::radiance(const Vec3f& d) const {
  float s, t;
  to_st(d, s, t);
  return texel(s, t);
}

bool LatLongMap::sample(float u0, float u1, Sample& out) const {
  const Distribution2D::Sample st = distribution_.sample(u0, u1);
  const float sin_theta = std::sin(kPi * st.y);
  if (!(st.pdf > 0) || !(sin_theta > 0)) return false;
  out.direction = from_st(st.x, st.y);
  out.radiance = texel(st.x, st.y);
  out.pdf = st.pdf / (2 * kPi * kPi * sin_theta);
  return true;
}

float LatLongMap::pdf(const Vec3f& d) const {
  float s, t;
  to_st(d, s, t);
  const float sin_theta = std::sin(kPi * t);
  return sin_theta > 0 ? distribution_.pdf(s, t) / (2 * kPi * kPi * sin_theta) : 0.0f;
}

}  // namespace darc
