// A 128-bit integer whose every operation checks for overflow: the exact arithmetic of `robust`'s
// integer stage (ccd_robust_integer.cpp). An overflow throws IntegerOverflow, which the stage
// catches to leave the query to the exact fallback: a value is never wrong, only refused.
// Private to fast/.
#pragma once

#include <cmath>
#include <cstdint>

namespace fdh {

struct IntegerOverflow {};

class Int128 {
 public:
  constexpr Int128(std::int64_t v = 0) : v_(v) {}  // NOLINT: converts like an integer

  int sign() const { return (v_ > 0) - (v_ < 0); }
  bool is_zero() const { return v_ == 0; }
  // The value as a double (rounded), for estimates only.
  double approx() const { return double(v_); }
  // |value| < 2^53: the double conversion is exact.
  bool fits_double() const { return v_ < (__int128(1) << 53) && -v_ < (__int128(1) << 53); }

  friend Int128 operator+(Int128 a, Int128 b) {
    Int128 r;
    if (__builtin_add_overflow(a.v_, b.v_, &r.v_)) throw IntegerOverflow{};
    return r;
  }
  friend Int128 operator-(Int128 a, Int128 b) {
    Int128 r;
    if (__builtin_sub_overflow(a.v_, b.v_, &r.v_)) throw IntegerOverflow{};
    return r;
  }
  friend Int128 operator*(Int128 a, Int128 b) {
    // Two factors within 64 bits never overflow (the common case, and a cheaper product).
    if (a.fits_64() && b.fits_64()) return from(__int128(std::int64_t(a.v_)) * std::int64_t(b.v_));
    Int128 r;
    if (__builtin_mul_overflow(a.v_, b.v_, &r.v_)) throw IntegerOverflow{};
    return r;
  }
  friend Int128 operator-(Int128 a) { return Int128() - a; }
  friend bool operator==(Int128 a, Int128 b) { return a.v_ == b.v_; }
  friend bool operator!=(Int128 a, Int128 b) { return a.v_ != b.v_; }
  friend bool operator<(Int128 a, Int128 b) { return a.v_ < b.v_; }
  friend bool operator<=(Int128 a, Int128 b) { return a.v_ <= b.v_; }

  // From a machine value, and back: for sums of products bounded by their factors' sizes.
  static Int128 of(__int128 v) { return from(v); }
  __int128 value() const { return v_; }
  bool fits_64() const { return v_ == __int128(std::int64_t(v_)); }

  // a / 2^k for a a multiple of 2^k (exact), and the number of trailing zero bits (128 for 0).
  Int128 shifted_right(int k) const { return from(v_ >> k); }
  int trailing_zeros() const {
    const unsigned __int128 u = static_cast<unsigned __int128>(v_);
    const auto lo = static_cast<std::uint64_t>(u), hi = static_cast<std::uint64_t>(u >> 64);
    return lo != 0 ? __builtin_ctzll(lo) : (hi != 0 ? 64 + __builtin_ctzll(hi) : 128);
  }

  // The integer square root of x >= 0 when x is a perfect square, else -1.
  friend Int128 exact_sqrt(Int128 x) {
    if (x.v_ < 0) return -1;
    // long double's 64-bit mantissa puts the estimate within a few units of the root (< 2^64).
    __int128 s = static_cast<__int128>(std::sqrt(static_cast<long double>(x.v_)));
    while (s > 0 && s * s > x.v_) --s;
    while ((s + 1) * (s + 1) <= x.v_) ++s;
    return s * s == x.v_ ? from(s) : from(-1);
  }

 private:
  static Int128 from(__int128 v) {
    Int128 r;
    r.v_ = v;
    return r;
  }
  __int128 v_;
};

}  // namespace fdh
