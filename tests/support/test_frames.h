// The RIB text of the small frames tests render: a camera and image set-up around a world the
// test writes, and the tiny scene the end-to-end tests of the command render.
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

// The world of a small test frame: a constant-coloured S-shaped cubic curve (width 0.1) in
// front of a sphere of radius 0.5 at the origin, seen from 5 units away with a 40 degree fov.
std::string tiny_world_rib();

// One frame of the tiny scene: FrameBegin `frame`, Display `display` with `mode`, WIDTHxHEIGHT,
// PixelSamples 1 1.
std::string tiny_frame_rib(int frame, const std::string& display, const std::string& mode = "rgba", int width = 32,
                           int height = 24);

}  // namespace darc::test
