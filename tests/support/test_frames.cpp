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

std::string tiny_world_rib() {
  return "WorldBegin\n"
         "  Surface \"constant\"\n"
         "  Color [1 0.5 0.25]\n"
         "  Curves \"cubic\" [4] \"nonperiodic\" \"P\" [-1 -1 0  -0.3 0.5 -0.5  0.3 -0.5 -0.5  1 1 0]"
         " \"constantwidth\" [0.1]\n"
         "  Color [0.2 0.4 0.9]\n"
         "  Sphere 0.5 -0.5 0.5 360\n"
         "WorldEnd\n";
}

std::string tiny_frame_rib(int frame, const std::string& display, const std::string& mode, int width, int height) {
  return "FrameBegin " + std::to_string(frame) + "\n" + "Display \"" + display + "\" \"file\" \"" + mode + "\"\n" +
         "Format " + std::to_string(width) + " " + std::to_string(height) + " 1\n" +
         "PixelSamples 1 1\n"
         "Projection \"perspective\" \"fov\" [40]\n"
         "Translate 0 0 5\n" +
         tiny_world_rib() + "FrameEnd\n";
}

}  // namespace darc::test
