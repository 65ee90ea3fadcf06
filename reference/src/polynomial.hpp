// Univariate polynomials in the time t with exact rational coefficients, and their real roots
// in [0, 1]: isolated by Sturm sequences, refined by bisection, with the exact sign of any other
// polynomial at a root. The algebra behind the exact CCD (exact_ccd.cpp); private to reference/.
//
// Why Sturm and bisection rather than CGAL's algebraic kernel: every polynomial here has degree
// <= 4 and we only ever ask "the roots in [0, 1], in order" and "the sign of g at this root".
// Sturm counts on dyadic points and a gcd answer both exactly in a page of code that a reader
// can check, with all rational arithmetic in GMP (see docs/methods.md).
#pragma once

#include <gmpxx.h>

#include <vector>

namespace fdh::exact::algebra {

struct Poly {
  std::vector<mpq_class> c;  // c[i] is the coefficient of t^i; no trailing zeros (0 is empty)

  Poly() = default;
  explicit Poly(std::vector<mpq_class> coefficients);
  static Poly linear(const mpq_class& at0, const mpq_class& at1);  // at0 + t (at1 - at0)

  int degree() const { return int(c.size()) - 1; }  // -1 for the zero polynomial
  bool is_zero() const { return c.empty(); }
  mpq_class operator()(const mpq_class& t) const;
  int sign_at(const mpq_class& t) const { return sgn((*this)(t)); }
};

Poly operator+(const Poly& a, const Poly& b);
Poly operator-(const Poly& a, const Poly& b);
Poly operator*(const Poly& a, const Poly& b);
Poly derivative(const Poly& p);
Poly remainder(const Poly& a, const Poly& b);  // b != 0
Poly quotient(const Poly& a, const Poly& b);   // exact division part; b != 0
Poly gcd(Poly a, Poly b);                      // monic; gcd(0, 0) = 0
Poly squarefree(const Poly& p);                // p / gcd(p, p'), p != 0

// A real root of a squarefree polynomial s: either the rational lo (= hi), or the only root of
// s in the open interval (lo, hi) with s(lo) s(hi) < 0. lo and hi are dyadic.
struct Root {
  const Poly* s = nullptr;
  mpq_class lo, hi;
  bool rational() const { return lo == hi; }
};

// The distinct real roots of p != 0 in [t0, t1], in increasing order. `p` must outlive them.
std::vector<Root> roots_in(const Poly& squarefree_p, const mpq_class& t0, const mpq_class& t1);

// The exact sign of g at the root (-1, 0, 1). May refine the root's interval.
int sign_at(const Poly& g, Root& r);

// Halves the root's interval until it is narrower than `width` (or the root is hit exactly).
void refine(Root& r, const mpq_class& width);

}  // namespace fdh::exact::algebra
