// Whether a double sum or a scaling by a power of two is exact: the checks behind every
// translation and scaling that must keep a query's truth (generator families, shrinking,
// metamorphic transforms). Plain IEEE additions; no multiplication, so no contraction.
#pragma once

#include <cmath>

namespace fdh {

// a + b = s + e exactly (Knuth's Two-Sum; Shewchuk 1997, Theorem 7), for a finite s.
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

// s = a + b; true when that sum is exact and finite (Two-Sum's error term is zero).
inline bool add_exactly(double a, double b, double& s) {
  double e;
  two_sum(a, b, s, e);
  return std::isfinite(s) && e == 0;
}

// s = x 2^e; true when that is exact: no overflow, no bits lost to underflow.
inline bool scale_exactly(double x, int e, double& s) {
  s = std::ldexp(x, e);
  return std::isfinite(s) && std::ldexp(s, -e) == x;
}

}  // namespace fdh
