#include "small_poly.hpp"

#include <initializer_list>

namespace fdh::small_poly {

int compare(const Fraction& a, const Fraction& b) {
  return (a.p * b.q - b.p * a.q).sign();
}

int sign_at(const Poly& f, const Fraction& t) {
  // Horner on the homogeneous form: ((c3 p + c2 q) p + c1 q^2) p + c0 q^3.
  Int128 v = f.c[3], qk = 1;
  for (int i = 2; i >= 0; --i) {
    qk = qk * t.q;
    v = v * t.p + f.c[i] * qk;
  }
  return v.sign();
}

namespace {

// p / q with q > 0.
Fraction fraction(Int128 p, Int128 q) {
  return q.sign() < 0 ? Fraction{-p, -q} : Fraction{p, q};
}
bool in_unit(const Fraction& t) {
  return t.p.sign() >= 0 && t.p <= t.q;
}

}  // namespace

// With s = sign(base(x)) and a = sign of base's leading coefficient: s a < 0 puts x strictly
// between the two roots; s a > 0 outside them, on the side of the vertex -c1 / (2 c2) that x is
// on; s = 0 cannot happen (the roots are irrational).
int compare(const Root& r, const Fraction& x) {
  if (r.rational) return compare(r.t, x);
  const Poly& b = r.base;
  const int s = sign_at(b, x), a = b.c[2].sign();
  if (s == 0) throw IntegerOverflow{};  // not an irrational root after all: refuse
  if (s * a < 0) return r.which;        // smaller root < x < larger root
  const int x_past_vertex = (Int128(2) * b.c[2] * x.p + b.c[1] * x.q).sign() * a;
  return x_past_vertex > 0 ? -1 : 1;
}

// g(r) for an irrational root r of base (c2 != 0): c2 g - g_d t^(d - 2) base has r as a root iff
// g does and lowers the degree, so down to a linear r1 t + r0, whose sign at r is that of r1
// times r against -r0 / r1.
int sign_at(const Poly& g, const Root& r) {
  if (r.rational) return sign_at(g, r.t);
  const Poly& b = r.base;
  Poly h = g;
  int factor = 1;
  for (int d = h.degree(); d >= 2; d = h.degree()) {
    Poly shifted;
    for (int i = 0; i <= 2; ++i) shifted.c[i + d - 2] = b.c[i];
    h = Poly{{b.c[2], 0, 0, 0}} * h - Poly{{h.c[d], 0, 0, 0}} * shifted;
    factor *= b.c[2].sign();
  }
  if (h.c[1].is_zero()) return factor * h.c[0].sign();
  return factor * h.c[1].sign() * compare(r, fraction(-h.c[0], h.c[1]));
}

int roots_in_unit(const Poly& f, Root out[2]) {
  const int d = f.degree();
  int n = 0;
  const auto keep = [&](const Fraction& t) {
    if (in_unit(t)) out[n++] = Root{true, t, {}, 0};
  };
  if (d == 1) keep(fraction(-f.c[0], f.c[1]));
  if (d != 2) return n;
  const Int128 c0 = f.c[0], c1 = f.c[1], c2 = f.c[2];
  // Bernstein coefficients on [0, 1] (times 2) of one strict sign: no root there, the common case.
  const int s0 = c0.sign(), s1 = (Int128(2) * c0 + c1).sign(), s2 = (c0 + c1 + c2).sign();
  if (s0 != 0 && s0 == s1 && s1 == s2) return 0;
  const Int128 disc = c1 * c1 - Int128(4) * c0 * c2;
  if (disc.sign() < 0) return 0;
  const Int128 s = exact_sqrt(disc);
  if (s.sign() >= 0) {  // rational: (-c1 -+ s) / (2 c2), the smaller first when c2 > 0
    const Int128 lo = c2.sign() > 0 ? -c1 - s : -c1 + s, hi = c2.sign() > 0 ? -c1 + s : -c1 - s;
    keep(fraction(lo, Int128(2) * c2));
    if (!s.is_zero()) keep(fraction(hi, Int128(2) * c2));
    return n;
  }
  for (const int which : {-1, 1}) {
    const Root r{false, {}, f, which};
    if (compare(r, Fraction{0, 1}) > 0 && compare(r, Fraction{1, 1}) < 0) out[n++] = r;
  }
  return n;
}

}  // namespace fdh::small_poly
