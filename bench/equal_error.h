// The equal-error comparison of the speed-against-error report: how long the stochastic hider
// needs to reach a given error, read off its measured (seconds, RMSE) curve.
//
// Between two measured sample counts we interpolate on a straight line in log-log space: a Monte
// Carlo estimator's RMSE falls as a power of its cost (RMSE ~ seconds^-1/2 for independent
// samples, faster for jittered ones), and a power law is a straight line in log-log, so this
// interpolation is exact for it whatever the exponent. Outside the measured range we do not
// extrapolate: the answer is then a bound, and says so.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>

namespace darc::bench {

// One measured setting: wall-clock seconds and RMSE against the reference.
struct SpeedErrorPoint {
  double seconds = 0;
  double rmse = 0;
};

enum class EqualErrorKind {
  Interpolated,      // between the two measured settings that bracket the target error
  CheapestSuffices,  // already the cheapest setting reaches the target: its time is an upper bound
  NotReached,        // no measured setting reaches the target: the costliest one's time is a lower bound
};

struct EqualErrorTime {
  EqualErrorKind kind = EqualErrorKind::NotReached;
  double seconds = 0;
};

// Floors that keep the logarithms finite: an RMSE of exactly 0 (identical images) or a time of 0
// (a clock that did not tick) would otherwise give -inf and then NaN.
inline constexpr double kMinLogRmse = 1e-12;
inline constexpr double kMinLogSeconds = 1e-9;

// The time the cheapest setting of `curve` whose RMSE is at most `target_rmse` would take, with
// the log-log interpolation described above between it and the next cheaper setting. `curve`
// is ordered by increasing cost (sample count). An empty curve gives NotReached with 0 seconds.
inline EqualErrorTime equal_error_time(std::span<const SpeedErrorPoint> curve, double target_rmse) {
  if (curve.empty()) return {EqualErrorKind::NotReached, 0};
  size_t first = 0;
  while (first < curve.size() && !(curve[first].rmse <= target_rmse)) ++first;
  if (first == curve.size()) return {EqualErrorKind::NotReached, curve.back().seconds};
  if (first == 0) return {EqualErrorKind::CheapestSuffices, curve.front().seconds};

  const SpeedErrorPoint& above = curve[first - 1];  // rmse > target
  const SpeedErrorPoint& below = curve[first];      // rmse <= target
  auto log_rmse = [](double r) { return std::log(std::max(r, kMinLogRmse)); };
  auto log_seconds = [](double s) { return std::log(std::max(s, kMinLogSeconds)); };
  double span_rmse = log_rmse(below.rmse) - log_rmse(above.rmse);
  // Equal logs after the floors: both are at the floor, take the cheaper time.
  double fraction = span_rmse != 0 ? (log_rmse(target_rmse) - log_rmse(above.rmse)) / span_rmse : 0.0;
  fraction = std::clamp(fraction, 0.0, 1.0);
  double log_t = log_seconds(above.seconds) + fraction * (log_seconds(below.seconds) - log_seconds(above.seconds));
  return {EqualErrorKind::Interpolated, std::exp(log_t)};
}

// "12.3", "<= 0.52" or ">= 40.1": a speed-up (equal-error time / the other hider's time) with
// the bound its EqualErrorKind implies.
inline std::string format_speedup(const EqualErrorTime& equal, double seconds) {
  const char* prefix = equal.kind == EqualErrorKind::CheapestSuffices ? "<= "
                       : equal.kind == EqualErrorKind::NotReached     ? ">= "
                                                                      : "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s%.3g", prefix, equal.seconds / std::max(seconds, kMinLogSeconds));
  return buf;
}

}  // namespace darc::bench
