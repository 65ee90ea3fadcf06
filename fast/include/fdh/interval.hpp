// Interval arithmetic in plain round-to-nearest: each result is pushed outward by more than its
// rounding error, so the true value of every expression lies inside its interval. No rounding
// mode switches and no library: the filters of the moving `robust` test (fdh/ccd/robust.hpp).
#pragma once

#include <cmath>

namespace fdh {

// Pushing x by |x| 2^-51 + 2^-1074 covers its rounding error (at most |x| 2^-53, or 2^-1075
// below the normal range) and the rounding of the push itself, which is at most |x| 2^-53 more.
inline double round_down(double x) {
  return x - (std::fabs(x) * 0x1p-51 + 0x1p-1074);
}
inline double round_up(double x) {
  return x + (std::fabs(x) * 0x1p-51 + 0x1p-1074);
}

struct Interval {
  double lo = 0, hi = 0;
  static Interval point(double x) { return {x, x}; }
  // Comparisons with NaN are false, so NaN bounds never certify a sign.
  bool positive() const { return lo > 0; }
  bool negative() const { return hi < 0; }
  bool excludes_zero() const { return lo > 0 || hi < 0; }
};

inline Interval operator+(const Interval& a, const Interval& b) {
  return {round_down(a.lo + b.lo), round_up(a.hi + b.hi)};
}
inline Interval operator-(const Interval& a, const Interval& b) {
  return {round_down(a.lo - b.hi), round_up(a.hi - b.lo)};
}
inline Interval operator*(const Interval& a, const Interval& b) {
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  const double mn12 = p1 < p2 ? p1 : p2, mn34 = p3 < p4 ? p3 : p4;
  const double mx12 = p1 < p2 ? p2 : p1, mx34 = p3 < p4 ? p4 : p3;
  return {round_down(mn12 < mn34 ? mn12 : mn34), round_up(mx12 < mx34 ? mx34 : mx12)};
}

}  // namespace fdh
