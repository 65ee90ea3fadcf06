// Doubles with fewer bits (fdh/gen/short_doubles.hpp), as both shrinkers write coordinates.
#include "fdh/gen/short_doubles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fdh::verify {
namespace {

TEST(ShortDoubles, SignificantBitsAreTheOddMantissas) {
  EXPECT_EQ(significant_bits(0), 0);
  EXPECT_EQ(significant_bits(std::numeric_limits<double>::infinity()), 0);
  EXPECT_EQ(significant_bits(1), 1);
  EXPECT_EQ(significant_bits(0.75), 2);  // 3 · 2^-2
  EXPECT_EQ(significant_bits(-5 * 1024.0), 3);
  EXPECT_EQ(significant_bits(0.1), 52);  // 0x1.999999999999ap-4: odd mantissa of 52 bits
  const OddMantissa m = odd_mantissa(-0.75);
  EXPECT_EQ(m.odd, 3u);
  EXPECT_EQ(m.exponent, -2);
}

TEST(ShortDoubles, CutTowardZeroOrRoundToNearest) {
  // 11.5 = 10111 · 2^-1: its top 3 bits are 101 (10 toward zero), rounded 110 (12).
  EXPECT_EQ(with_bits(11.5, 3, Rounding::TowardZero), 10);
  EXPECT_EQ(with_bits(11.5, 3, Rounding::Nearest), 12);
  EXPECT_EQ(with_bits(-11.5, 3, Rounding::TowardZero), -10);
  EXPECT_EQ(with_bits(-11.5, 3, Rounding::Nearest), -12);
  EXPECT_EQ(with_bits(9, 2, Rounding::Nearest), 8);        // 1001: a tie, to even (10 · 2^2)
  EXPECT_EQ(with_bits(0.75, 8, Rounding::Nearest), 0.75);  // short enough already
  const double tiny = std::ldexp(0x1.ep0, -1070);          // subnormal: 30 · 2^-1074
  EXPECT_EQ(with_bits(tiny, 1, Rounding::TowardZero), std::ldexp(1.0, -1070));
  EXPECT_EQ(with_bits(0.0, 1, Rounding::Nearest), 0.0);
  EXPECT_EQ(significant_bits(with_bits(0.1, 16, Rounding::TowardZero)), 14);  // 0x1.9998p-4
}

}  // namespace
}  // namespace fdh::verify
