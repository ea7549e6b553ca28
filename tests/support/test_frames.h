// The RIB text of the small frames tests render: a camera and image set-up around a world the
// test writes.
#pragma once

#include <string>

namespace darc::test {

// A `width` x `height` orthographic frame, one world unit per pixel (pixel (i, j) is centred on
// x = i + 0.5 - width / 2, y = height / 2 - j - 0.5), `samples` x `samples` pixel samples, box
// filter, Surface "constant", and `world` inside WorldBegin/WorldEnd.
std::string orthographic_frame(int width, int height, int samples, const std::string& world);

// The same with a perspective camera of `fov_degrees`, with `camera` (transforms) before
// WorldBegin.
std::string perspective_frame(int width, int height, int samples, float fov_degrees, const std::string& camera,
                              const std::string& world);

}  // namespace darc::test
