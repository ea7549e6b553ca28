#include "support/image_files.h"

#include <OpenImageIO/imagebuf.h>

#include <cstring>

namespace darc::test {

bool Pixels::identical_to(const Pixels& o) const {
  return width == o.width && height == o.height && channels == o.channels && v.size() == o.v.size() &&
         std::memcmp(v.data(), o.v.data(), v.size() * sizeof(float)) == 0;
}

bool read_image(const std::filesystem::path& p, Pixels& out) {
  OIIO::ImageBuf buf(p.string());
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return false;
  const OIIO::ImageSpec& s = buf.spec();
  out.width = s.width;
  out.height = s.height;
  out.channels = s.nchannels;
  out.v.resize(size_t(s.width) * s.height * s.nchannels);
  // The data window, wherever it starts (a crop's does not start at 0, 0).
  return buf.get_pixels(OIIO::ROI(s.x, s.x + s.width, s.y, s.y + s.height, 0, 1, 0, s.nchannels), OIIO::TypeDesc::FLOAT,
                        out.v.data());
}

std::optional<OIIO::ImageSpec> read_image_header(const std::filesystem::path& p) {
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return std::nullopt;
  return in->spec();
}

}  // namespace darc::test
