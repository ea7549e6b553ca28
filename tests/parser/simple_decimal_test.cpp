// The fast decimal path gives bitwise the double std::from_chars gives, on the plain decimals it
// accepts, and refuses what it must leave to from_chars.
#include "parser/simple_decimal.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace darc {
namespace {

double from_chars_value(const std::string& s) {
  double v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

TEST(SimpleDecimal, MatchesFromCharsBitwise) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> digits(1, 15), point(-1, 15), sign(0, 1);
  int accepted = 0;
  for (int i = 0; i < 200000; ++i) {
    std::string s = sign(rng) ? "-" : "";
    int n = digits(rng), at = point(rng);
    for (int k = 0; k < n; ++k) {
      if (k == at) s += '.';
      s += char('0' + rng() % 10);
    }
    double fast = 0;
    const char* end = nullptr;
    if (!parse_simple_decimal(s.data(), s.data() + s.size(), fast, end)) continue;
    ++accepted;
    ASSERT_EQ(end, s.data() + s.size()) << s;
    ASSERT_EQ(std::bit_cast<uint64_t>(fast), std::bit_cast<uint64_t>(from_chars_value(s))) << s;
    // And so the float the parser keeps.
    ASSERT_EQ(std::bit_cast<uint32_t>(float(fast)), std::bit_cast<uint32_t>(float(from_chars_value(s)))) << s;
  }
  EXPECT_GT(accepted, 150000);
}

TEST(SimpleDecimal, LeavesTheRestToFromChars) {
  double v = 7;
  const char* end = nullptr;
  for (const char* s : {"1e5", "2.5E-3", ".", "-", "", "1234567890123456", "abc"}) {
    std::string t = s;
    EXPECT_FALSE(parse_simple_decimal(t.data(), t.data() + t.size(), v, end)) << s;
  }
  EXPECT_EQ(v, 7);
  std::string t = "-0.0500]";
  ASSERT_TRUE(parse_simple_decimal(t.data(), t.data() + t.size(), v, end));
  EXPECT_EQ(v, -0.05);
  EXPECT_EQ(*end, ']');
  t = "-0";
  ASSERT_TRUE(parse_simple_decimal(t.data(), t.data() + t.size(), v, end));
  EXPECT_TRUE(std::signbit(v));
}

}  // namespace
}  // namespace darc
