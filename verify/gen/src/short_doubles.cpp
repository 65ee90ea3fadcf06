#include "fdh/gen/short_doubles.hpp"

#include <cmath>

namespace fdh::verify {

int OddMantissa::bits() const {
  int n = 0;
  for (std::uint64_t m = odd; m; m >>= 1) ++n;
  return n;
}

OddMantissa odd_mantissa(double v) {
  int exp = 0;
  const double f = std::frexp(std::fabs(v), &exp);
  OddMantissa m{std::uint64_t(std::ldexp(f, 53)), exp - 53};  // an integer below 2^53
  for (; (m.odd & 1) == 0; m.odd >>= 1) ++m.exponent;
  return m;
}

int significant_bits(double v) {
  if (v == 0 || !std::isfinite(v)) return 0;
  return odd_mantissa(v).bits();
}

double with_bits(double v, int bits, Rounding rounding) {
  if (v == 0 || !std::isfinite(v) || significant_bits(v) <= bits) return v;
  // v scaled (exactly, by a power of two) so that its top `bits` bits are the integer part.
  const int shift = bits - 1 - std::ilogb(v);
  const double scaled = std::ldexp(v, shift);
  const double cut = rounding == Rounding::TowardZero ? std::trunc(scaled) : std::nearbyint(scaled);
  return std::ldexp(cut, -shift);
}

}  // namespace fdh::verify
