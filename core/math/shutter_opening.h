// How the shutter opens (PRMan's Camera "shutteropening" [a b]): over the shutter-normalised
// interval [0, 1] the shutter opens linearly from 0 to a, is fully open from a to b and closes
// linearly from b to 1, so that a moment of the shutter counts in proportion to how open it is
// then (the trapezoid density t/a, 1, (1-t)/(1-b), of area A = (1 + b - a)/2). The default
// [0 1] is a box shutter: every moment counts the same.
//
// The hiders sample time through time_at: a uniform u in [0, 1] (stratified, jittered) maps to a
// time whose distribution is the trapezoid's (its inverse CDF), so that strata of u stay strata
// of equal weight.
#pragma once

#include <algorithm>
#include <cmath>

namespace darc {

struct ShutterOpening {
  double fully_open = 0;     // a: the shutter has opened fully
  double starts_closing = 1;  // b: the shutter begins to close

  bool is_box() const { return fully_open == 0 && starts_closing == 1; }

  // The time at which the trapezoid's CDF reaches u (u in [0, 1]); u itself for the box.
  float time_at(float u) const {
    if (is_box()) return u;
    const double a = fully_open, b = starts_closing;
    const double area = 0.5 * (1 + b - a);
    const double v = std::clamp(double(u), 0.0, 1.0) * area;
    double t;
    if (v < 0.5 * a) {
      t = std::sqrt(2 * a * v);
    } else if (v <= 0.5 * a + (b - a)) {
      t = v + 0.5 * a;
    } else {
      t = 1 - std::sqrt(std::max(0.0, 2 * (1 - b) * (area - v)));
    }
    return float(std::clamp(t, 0.0, 1.0));
  }
};

}  // namespace darc
