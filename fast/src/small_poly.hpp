// Polynomials in t of degree <= 3 with exact integer coefficients (checked_int.hpp), exact
// times as fractions, and the exact roots in [0, 1] of those of degree <= 2: a fraction, or an
// irrational root of a quadratic held as the quadratic itself. The algebra of `robust`'s integer
// stage (ccd_robust_integer.cpp). Private to fast/.
#pragma once

#include "checked_int.hpp"

namespace fdh::small_poly {

// A time t = p / q, q > 0.
struct Fraction {
  Int128 p = 0, q = 1;
};
int compare(const Fraction& a, const Fraction& b);  // sign(a - b)

// c[0] + c[1] t + c[2] t^2 + c[3] t^3. A product beyond degree 3 throws IntegerOverflow.
struct Poly {
  Int128 c[4] = {0, 0, 0, 0};
  int degree() const {  // -1 for 0
    return !c[3].is_zero()   ? 3
           : !c[2].is_zero() ? 2
           : !c[1].is_zero() ? 1
           : c[0].is_zero()  ? -1
                             : 0;
  }
  bool is_zero() const {
    return c[0].is_zero() && c[1].is_zero() && c[2].is_zero() && c[3].is_zero();
  }
};
// Inline: the integer stage's hot loop (cross and dot products of moving points).
inline Poly operator+(const Poly& a, const Poly& b) {
  return {{a.c[0] + b.c[0], a.c[1] + b.c[1], a.c[2] + b.c[2], a.c[3] + b.c[3]}};
}
inline Poly operator-(const Poly& a, const Poly& b) {
  return {{a.c[0] - b.c[0], a.c[1] - b.c[1], a.c[2] - b.c[2], a.c[3] - b.c[3]}};
}
inline Poly operator*(const Poly& a, const Poly& b) {
  const int da = a.degree(), db = b.degree();
  Poly r;
  if (da < 0 || db < 0) return r;
  if (da + db > 3) throw IntegerOverflow{};
  for (int i = 0; i <= da; ++i)
    for (int j = 0; j <= db; ++j) r.c[i + j] = r.c[i + j] + a.c[i] * b.c[j];
  return r;
}

// The sign of f(p / q): of the homogeneous sum of c_i p^i q^(3 - i), q^3 > 0.
int sign_at(const Poly& f, const Fraction& t);

// A root in [0, 1] of a polynomial of degree 1 or 2: the fraction t, or (rational false) the
// smaller (which = -1) or larger (+1) root of the quadratic `base`, whose discriminant is not a
// square: irrational, so no fraction is ever equal to it.
struct Root {
  bool rational = true;
  Fraction t;
  Poly base;
  int which = 0;
};
int compare(const Root& r, const Fraction& x);  // sign(r - x)
int sign_at(const Poly& g, const Root& r);      // g of degree <= 3

// The distinct roots in [0, 1] of f (degree <= 2, not 0), increasing; returns how many.
int roots_in_unit(const Poly& f, Root out[2]);

}  // namespace fdh::small_poly
