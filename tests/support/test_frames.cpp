#include "support/test_frames.h"

#include <iomanip>
#include <sstream>

namespace darc::test {

std::string orthographic_frame(int width, int height, int samples, const std::string& world) {
  std::ostringstream s;
  s << std::setprecision(9) << "Format " << width << " " << height << " 1\n"
    << "PixelSamples " << samples << " " << samples << "\n"
    << "PixelFilter \"box\" 1 1\n"
    << "Projection \"orthographic\"\n"
    << "ScreenWindow " << -0.5 * width << " " << 0.5 * width << " " << -0.5 * height << " " << 0.5 * height << "\n"
    << "WorldBegin\nSurface \"constant\"\n"
    << world << "WorldEnd\n";
  return s.str();
}

std::string perspective_frame(int width, int height, int samples, float fov_degrees, const std::string& camera,
                              const std::string& world) {
  std::ostringstream s;
  s << std::setprecision(9) << "Format " << width << " " << height << " 1\n"
    << "PixelSamples " << samples << " " << samples << "\n"
    << "PixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [" << fov_degrees << "]\n"
    << camera << "\nWorldBegin\nSurface \"constant\"\n"
    << world << "WorldEnd\n";
  return s.str();
}

}  // namespace darc::test
