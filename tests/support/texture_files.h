// Image files the texture and dome tests read: written through OpenImageIO into a scratch folder.
#pragma once

#include <functional>
#include <string>

#include "core/math/vec.h"
#include "support/darc_command.h"

namespace darc::test {

// A float RGB image of width x height whose pixel at (s, t) (pixel centres in [0, 1)^2, t down
// the rows) is rgb(s, t), written as `name` in `dir`; its path.
std::string write_rgb_image(const ScratchDir& dir, const std::string& name, int width, int height,
                            const std::function<Vec3f(float s, float t)>& rgb);

// 64 x 64 "quadrants.exr": the left half red, the right half blue; the top half (t < 0.5) 1, the
// bottom 0.5. Orientation tests read which quarter they see.
std::string write_quadrants_texture(const ScratchDir& dir);

}  // namespace darc::test
