// Shirley and Chiu's concentric map of the unit square onto the unit disc: it keeps areas in
// proportion and strata compact, so stratified square samples stay stratified on the disc (area
// lights, the lens of DepthOfField).
#pragma once

#include "core/math/vec.h"

#include <cmath>
#include <numbers>

namespace darc {

// (u0, u1) in [0, 1)^2 to a point of the unit disc.
inline Vec2f concentric_disc(float u0, float u1) {
  const float x = 2 * u0 - 1, y = 2 * u1 - 1;
  if (x == 0 && y == 0) return {0, 0};
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4;
  float r, theta;
  if (std::abs(x) > std::abs(y)) {
    r = x;
    theta = kQuarterPi * (y / x);
  } else {
    r = y;
    theta = 2 * kQuarterPi - kQuarterPi * (x / y);
  }
  return {r * std::cos(theta), r * std::sin(theta)};
}

}  // namespace darc
