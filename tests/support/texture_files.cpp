#include "support/texture_files.h"

#include <OpenImageIO/imagebuf.h>

#include <gtest/gtest.h>

namespace darc::test {

std::string write_rgb_image(const ScratchDir& dir, const std::string& name, int width, int height,
                            const std::function<Vec3f(float s, float t)>& rgb) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Vec3f c = rgb((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      const float v[3] = {c.x, c.y, c.z};
      image.setpixel(x, y, v);
    }
  const std::string path = (dir / name).string();
  EXPECT_TRUE(image.write(path)) << path;
  return path;
}

std::string write_quadrants_texture(const ScratchDir& dir) {
  return write_rgb_image(dir, "quadrants.exr", 64, 64, [](float s, float t) {
    const float v = t < 0.5f ? 1.0f : 0.5f;
    return s < 0.5f ? Vec3f{v, 0, 0} : Vec3f{0, 0, v};
  });
}

}  // namespace darc::test
