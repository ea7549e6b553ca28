// Images as the darc command wrote them, read back through OpenImageIO: the pixels as floats and
// the header.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <optional>
#include <vector>

namespace darc::test {

// Pixels as float RGBA (or fewer channels), row-major.
struct Pixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> v;
  float at(int x, int y, int c) const { return v[(size_t(y) * width + x) * channels + c]; }
  // Same size, same channels, every value bitwise equal (as floats read back).
  bool identical_to(const Pixels& o) const;
};

// Reads every channel of the first subimage of `p` as floats into `out` (its data window: pixel
// (0, 0) of `out` is the data window's corner); false when it does not open or read.
bool read_image(const std::filesystem::path& p, Pixels& out);

// The header (size, channels, metadata) of an image file; nullopt when it does not open.
std::optional<OIIO::ImageSpec> read_image_header(const std::filesystem::path& p);

}  // namespace darc::test
