// A fast path for the plain decimals that fill numeric RIB ("0.6221", "-12", ".5"): digits with
// at most one point, no exponent, at most 15 significant digits and 22 after the point. Their
// value is an integer below 2^53 divided by an exact power of ten, so one IEEE division gives the
// correctly rounded double, the same double std::from_chars gives (Clinger 1990). Anything else
// is left to std::from_chars.
#pragma once

#include <cstdint>

namespace darc {

// Parses the decimal at [first, last). Returns false (value untouched) when it is not of the
// simple form; else sets value and `end` to the first byte after the number.
inline bool parse_simple_decimal(const char* first, const char* last, double& value, const char*& end) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  constexpr int kMaxDigits = 15;    // 10^15 < 2^53: the mantissa is exact
  constexpr int kMaxFraction = 22;  // 10^22 is the largest exact power of ten in a double
  const char* p = first;
  bool negative = false;
  if (p < last && *p == '-') {
    negative = true;
    ++p;
  }
  uint64_t mantissa = 0;
  int digits = 0, fraction = 0;
  bool point = false, any = false;
  for (; p < last; ++p) {
    const char c = *p;
    if (c >= '0' && c <= '9') {
      any = true;
      if (mantissa == 0 && c == '0' && !point) continue;  // leading zeros cost nothing
      if (++digits > kMaxDigits) return false;
      mantissa = mantissa * 10 + uint64_t(c - '0');
      if (point) ++fraction;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  if (!any || fraction > kMaxFraction) return false;
  if (p < last && (*p == 'e' || *p == 'E')) return false;  // exponents: from_chars
  // Leading zeros after the point still count as fraction digits.
  double v = double(mantissa) / kPow10[fraction];
  value = negative ? -v : v;
  end = p;
  return true;
}

}  // namespace darc
