// Doubles written with fewer bits: what both shrinkers try on a coordinate (simplify.hpp for
// queries, shrink_point_sets.hpp for point sets), and how they count its bits.
#pragma once

#include <cstdint>

namespace fdh::verify {

// v = ±odd · 2^exponent with odd odd: v's significand without its trailing zeros. For v finite,
// not 0.
struct OddMantissa {
  std::uint64_t odd = 0;
  int exponent = 0;
  int bits() const;  // the bit length of odd: v's significant bits
};
OddMantissa odd_mantissa(double v);

// v's significant bits; 0 for 0 and for infinities and NaN.
int significant_bits(double v);

// v with at most `bits` significant bits (bits >= 1), rounded toward zero (a coordinate that only
// gets shorter and nearer 0) or to nearest, ties to even; v itself when it has no more bits, or
// is 0 or not finite.
enum class Rounding { TowardZero, Nearest };
double with_bits(double v, int bits, Rounding rounding);

}  // namespace fdh::verify
