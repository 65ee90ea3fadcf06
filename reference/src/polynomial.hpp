// Univariate polynomials in the time t with integer coefficients, and their real roots in a
// dyadic window: isolated by Bernstein bisection on [0, 1] or Sturm sequences, refined by
// bisection, with the exact sign of any other polynomial at a root. The algebra behind the
// exact CCD (exact_ccd.cpp); private to reference/.
//
// Integers only: the query's doubles are scaled by one power of two into integers, every
// polynomial then has integer coefficients, every point where we evaluate is dyadic (a / 2^k),
// and remainders are pseudo-remainders scaled by positive factors. No rational is ever
// normalized, which is where GMP rationals spend their time. The integers are Int
// (integer.hpp): machine integers while they fit, GMP's mpn layer on inline limbs beyond.
//
// Why Sturm and bisection rather than CGAL's algebraic kernel: every polynomial here has degree
// <= 6 (4 for contact, 6 for a minimum separation) and we only ever ask "the roots in [t0, t1], in
// order" and "the sign of g at this root". Sturm counts and a gcd answer both exactly in a page of
// code (see docs/methods.md).
#pragma once

#include <gmpxx.h>

#include "inline_vector.hpp"
#include "integer.hpp"

#include <initializer_list>

namespace fdh::exact::algebra {

// Every polynomial here has degree <= 6: 4 for contact (a dot product of two cross products of
// moving vectors), 6 for a minimum separation (the square of a distance to a plane times |n|^2,
// exact_separation.cpp). Its coefficients stay inside it; unused capacity is never constructed,
// so contact pays nothing for it.
constexpr int kMaxDegree = 6;
using Coeffs = InlineVector<Int, kMaxDegree + 1>;

struct Poly {
  Coeffs c;  // c[i] is the coefficient of t^i; no trailing zeros (0 is empty)

  Poly() = default;
  explicit Poly(Coeffs coefficients);
  static Poly linear(const Int& at0, const Int& at1);  // at0 + t (at1 - at0)

  int degree() const { return int(c.size()) - 1; }  // -1 for the zero polynomial
  void trim();                                      // drops trailing zero coefficients
  bool is_zero() const { return c.empty(); }
};

Poly operator+(const Poly& a, const Poly& b);
Poly operator-(const Poly& a, const Poly& b);
Poly operator*(const Poly& a, const Poly& b);
// A term of sum_of_products: a b, or -a b.
struct Product {
  const Poly& a;
  const Poly& b;
  bool minus = false;
};
// The sum of the terms, accumulated in place: no product becomes a polynomial of its own. The
// cross and dot products are made of these.
Poly sum_of_products(std::initializer_list<Product> terms);
Poly derivative(const Poly& p);
Poly gcd(const Poly& a, const Poly& b);  // primitive, positive leading coefficient; gcd(0,0) = 0

// True if p certainly has no root in [0, 1]: its Bernstein coefficients on [0, 1] all have
// one strict sign. A cheap exact test before gcds and Sturm sequences.
bool no_root_in_unit(const Poly& p);

// A double as m 2^e exactly, m odd (0 = 0 2^0): the fewest bits.
struct Binary {
  long m = 0;
  int e = 0;
  static Binary of(double x);
};

// The dyadic number a / 2^k.
struct Dyadic {
  Int a;
  unsigned long k = 0;
  static Dyadic of(double x);  // exact, with the smallest k >= 0
  mpq_class value() const;
};
int sign_at(const Poly& p, const Dyadic& t);
// Whether [t0, t1] is [0, 1]: the window where Bernstein coefficients decide most roots.
bool is_unit_window(const Dyadic& t0, const Dyadic& t1);

// A real root of a squarefree polynomial s: either lo (= hi), or the only root of s in the open
// interval (lo, hi) with s(lo) s(hi) < 0. lo = a / 2^k and hi = b / 2^k share k.
struct Root {
  const Poly* s = nullptr;
  Int a, b;
  unsigned long k = 0;
  bool narrowed = false;  // by the one-step float bisection (polynomial.cpp), once is enough
  static Root at(const Dyadic& t) { return Root{nullptr, t.a, t.a, t.k, false}; }
  bool exact() const { return a == b; }
  Dyadic lo() const { return {a, k}; }
  Dyadic hi() const { return {b, k}; }
};

using Roots = InlineVector<Root, kMaxDegree>;

// The distinct real roots of s in [t0, t1], increasing, for s of degree >= 1. s becomes its
// squarefree part s / gcd(s, s') if it has a multiple root. The roots point into s, which must
// outlive them.
Roots roots_in(Poly& s, const Dyadic& t0, const Dyadic& t1);

// The exact sign of g at the root (-1, 0, 1). May refine the root's interval.
int sign_at(const Poly& g, Root& r);

// Halves the root's interval until it is narrower than 2^-bits (or hits the root exactly).
void refine(Root& r, unsigned long bits);

// Shrinks the root's interval in one step to two adjacent doubles where a floating-point
// bisection finds them (checked exactly: unchanged where rounding fooled it); once per root.
// Some 50 exact bisections saved when a narrow interval is wanted.
void narrow_to_doubles(Root& r);

// The sign of x - y, exactly.
int compare(const Dyadic& x, const Dyadic& y);

}  // namespace fdh::exact::algebra
