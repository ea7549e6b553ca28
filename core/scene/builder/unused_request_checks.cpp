#include "core/scene/builder/unused_request_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

namespace darc {

namespace {

// How many numbers a request takes; requests not listed take any count (MotionBegin's times,
// ColorSamples' matrices) or none that matter.
struct NumberCount {
  std::string_view request;
  size_t count;
};
constexpr NumberCount kCounts[] = {
    {"ShadingRate", 1}, {"RelativeDetail", 1}, {"PixelVariance", 1}, {"GeometricApproximation", 1},
    {"DetailRange", 4}, {"Bound", 6},       {"Detail", 6}};

// ColorSamples' two matrices when they change nothing: 3 samples, RGB to RGB and back.
constexpr std::array<double, 18> kRgbColorSamples = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1};

class UnusedValueWarnings {
 public:
  UnusedValueWarnings(const std::string& request, Diagnostics& diag, const SourceLoc& loc)
      : request_(request), diag_(diag), loc_(loc) {}

  // Warns unless `ok`; `what` names the value and the RI rule it breaks.
  void expect(bool ok, const std::string& what) {
    if (!ok) diag_.warning(loc_, request_, what + " (RI Spec 3.2); darc does not use it");
  }

 private:
  const std::string& request_;
  Diagnostics& diag_;
  const SourceLoc& loc_;
};

// Bound and Detail: xmin xmax ymin ymax zmin zmax.
void check_bound(const std::vector<double>& b, UnusedValueWarnings& w) {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = b[2 * axis], hi = b[2 * axis + 1];
    w.expect(lo <= hi, fmt::format("the bound's {}min {} is above its {}max {}", kAxes[axis], lo, kAxes[axis], hi));
  }
}

}  // namespace

void check_unused_request_values(const std::string& request, const std::vector<double>& n, Diagnostics& diag,
                                 const SourceLoc& loc) {
  UnusedValueWarnings w(request, diag, loc);
  if (request == "ColorSamples") {
    const bool rgb = n.size() == kRgbColorSamples.size() && std::equal(n.begin(), n.end(), kRgbColorSamples.begin());
    if (!rgb)
      diag.warning(loc, request,
                   n.size() == kRgbColorSamples.size()
                       ? std::string("RGB conversion matrices other than the identity are not supported: colours "
                                     "stay RGB")
                       : fmt::format("N = {} samples per colour is not supported: colours stay RGB", n.size() / 6));
    return;
  }
  for (const NumberCount& c : kCounts) {
    if (c.request != request) continue;
    if (n.size() != c.count) {
      w.expect(false, fmt::format("takes {} number{}, found {}", c.count, c.count == 1 ? "" : "s", n.size()));
      return;
    }
  }
  if (request == "ShadingRate") {
    w.expect(n[0] > 0, fmt::format("size {} must be positive", n[0]));
  } else if (request == "RelativeDetail" || request == "PixelVariance" || request == "GeometricApproximation") {
    w.expect(n[0] >= 0, fmt::format("value {} must not be negative", n[0]));
  } else if (request == "DetailRange") {
    w.expect(n[0] <= n[1] && n[1] <= n[2] && n[2] <= n[3],
             fmt::format("[{} {} {} {}] must not decrease", n[0], n[1], n[2], n[3]));
  } else if (request == "Bound" || request == "Detail") {
    check_bound(n, w);
  }
}

}  // namespace darc
