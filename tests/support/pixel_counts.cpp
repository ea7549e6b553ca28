#include "support/pixel_counts.h"

#include <algorithm>

namespace darc::test {

int count_pixels(const Pixels& p, const PixelTest& on) {
  int n = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      if (on(p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2))) ++n;
  return n;
}

int max_runs_along_rows(const Pixels& p, const PixelTest& on) {
  int best = 0;
  for (int y = 0; y < p.height; ++y) {
    int runs = 0;
    bool prev = false;
    for (int x = 0; x < p.width; ++x) {
      const bool v = on(p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2));
      if (v && !prev) ++runs;
      prev = v;
    }
    best = std::max(best, runs);
  }
  return best;
}

}  // namespace darc::test
