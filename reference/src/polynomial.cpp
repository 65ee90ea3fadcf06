#include "polynomial.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

namespace fdh::exact::algebra {
namespace {

void trim(Coeffs& c) {
  while (!c.empty() && c.back().is_zero()) c.pop_back();
}

Int shifted(const Int& x, unsigned long bits) {
  return x << bits;
}

// p divided by the gcd of its coefficients, with a positive leading coefficient.
Poly primitive(Poly p) {
  if (p.is_zero()) return p;
  Int g = 0;
  for (const Int& x : p.c) g = gcd(g, x);
  if (p.c.back().sign() < 0) g = -g;
  for (Int& x : p.c) x = divexact(x, g);
  return p;
}

// A positive multiple of the remainder of a by b: each step scales by |lc(b)| > 0, so signs
// at every point are those of the true remainder (what Sturm sequences need).
Poly pseudo_remainder(const Poly& a, const Poly& b) {
  Coeffs r = a.c;
  const Int lb = abs(b.c.back());
  const int sb = b.c.back().sign();
  const std::size_t n = b.c.size();
  Int lr;
  while (r.size() >= n) {
    lr = sb < 0 ? -r.back() : r.back();
    const std::size_t e = r.size() - n;
    for (Int& x : r) mul(x, x, lb);
    for (std::size_t j = 0; j < n; ++j) submul(r[e + j], lr, b.c[j]);
    r.pop_back();  // now zero
    trim(r);
  }
  return Poly(std::move(r));
}

// The Sturm sequence of s: s, s', then negated remainders down to a constant when s is
// squarefree, else down to gcd(s, s') (up to a factor).
InlineVector<Poly, kMaxDegree + 1> sturm_sequence(const Poly& s) {
  InlineVector<Poly, kMaxDegree + 1> seq{s, derivative(s)};
  while (!seq.back().is_zero() && seq.back().degree() > 0) {
    Poly r = pseudo_remainder(seq[seq.size() - 2], seq.back());
    if (r.is_zero()) break;
    for (Int& x : r.c) x = -x;
    seq.push_back(std::move(r));
  }
  return seq;
}

// What isolation needs at a point t: the sign variations V of the Sturm sequence there, zeros
// dropped, and the sign of s itself (the sequence's first element). For squarefree s,
// V(a) - V(b) is the number of distinct roots in (a, b] (Sturm's theorem, half-open).
struct SturmAt {
  int v = 0, s = 0;
};

struct Isolator {
  const Poly& s;
  InlineVector<Poly, kMaxDegree + 1> seq;
  Roots out;

  SturmAt at(const Int& a, unsigned long k) const {
    SturmAt r;
    int last = 0;
    for (const Poly& p : seq) {
      const int sp = sign_at(p, Dyadic{a, k});
      if (&p == &seq[0]) r.s = sp;
      if (sp == 0) continue;
      if (last != 0 && sp != last) ++r.v;
      last = sp;
    }
    return r;
  }

  // Appends the roots in (a, b] / 2^k, in order, given the sequence at both ends (each point is
  // evaluated once).
  void isolate(const Int& a0, const Int& b0, unsigned long k, SturmAt fa, SturmAt fb) {
    const int n = fa.v - fb.v;
    if (n == 0) return;
    if (n > 1) {
      const Int m = a0 + b0;
      const SturmAt fm = at(m, k + 1);
      isolate(a0 << 1, m, k + 1, fa, fm);
      isolate(m, b0 << 1, k + 1, fm, fb);
      return;
    }
    if (fb.s == 0) {
      out.push_back(Root{&s, b0, b0, k});
      return;
    }
    // One root in (a, b). Move a off a root of s so that s changes sign across (a, b).
    Int a = a0, b = b0;
    while (fa.s == 0) {
      const Int m = a + b;
      a = a << 1, b = b << 1, ++k;
      const SturmAt fm = at(m, k);
      if (fm.s == 0) {
        out.push_back(Root{&s, m, m, k});
        return;
      }
      if (fm.v - fb.v == 1)
        a = m, fa = fm;
      else
        b = m, fb = fm;
    }
    out.push_back(Root{&s, a, b, k});
  }
};

// Halves the interval; false if the midpoint is the root.
bool bisect_once(Root& r) {
  const Int m = r.a + r.b;
  r.a = r.a << 1, r.b = r.b << 1, ++r.k;
  const int sm = sign_at(*r.s, Dyadic{m, r.k});
  if (sm == 0) {
    r.a = r.b = m;
    return false;
  }
  (sign_at(*r.s, r.lo()) == sm ? r.a : r.b) = m;
  return true;
}

// Dyadic value as a double, rounded to nearest (exact for the endpoints we make).
double to_double(const Int& a, unsigned long k) {
  long e = 0;
  const double m = a.frexp(&e);
  return std::ldexp(m, int(e - long(k)));
}

// Shrinks the root's interval in one step to two adjacent doubles: bisection in floating point
// on s, then an exact check that s changes sign between them. A failed check (rounding fooled
// the float bisection) changes nothing. Replaces some 50 exact bisections.
void jump(Root& r) {
  const Poly& s = *r.s;
  const int d = s.degree();
  // s's coefficients as doubles scaled by a common power of two (tiny ones may underflow: the
  // float bisection only has to be good, the exact check makes it safe).
  double c[kMaxDegree + 1], m[kMaxDegree + 1];
  long e[kMaxDegree + 1];
  long emax = LONG_MIN;
  for (int i = 0; i <= d; ++i) {
    m[i] = s.c[i].frexp(&e[i]);
    if (m[i] != 0 && e[i] > emax) emax = e[i];
  }
  for (int i = 0; i <= d; ++i) c[i] = m[i] != 0 ? std::ldexp(m[i], int(e[i] - emax)) : 0;
  const auto f = [&](double t) {
    double v = 0;
    for (int i = d; i >= 0; --i) v = v * t + c[i];
    return v;
  };
  double lo = to_double(r.a, r.k), hi = to_double(r.b, r.k);
  const bool neg_lo = f(lo) < 0;
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    const double v = f(mid);
    if (v == 0) break;
    ((v < 0) == neg_lo ? lo : hi) = mid;
  }
  // Where rounding noise spread the float bisection's answer (s evaluated in doubles near its
  // root), the two doubles may both lie on one side: then once more, 2^-40 wider on each side.
  for (const double pad : {0.0, 0x1p-40}) {
    const Dyadic dl = Dyadic::of(lo - pad), dh = Dyadic::of(hi + pad);
    const unsigned long k = std::max({r.k, dl.k, dh.k});
    const Int a = shifted(dl.a, k - dl.k), b = shifted(dh.a, k - dh.k);
    const Int ra = shifted(r.a, k - r.k), rb = shifted(r.b, k - r.k);
    if (!(ra <= a && a < b && b <= rb)) return;
    const int sa = sign_at(s, Dyadic{a, k}), sb = sign_at(s, Dyadic{b, k});
    if (sa == 0 || sb == 0) {
      r.a = r.b = sa == 0 ? a : b;
      r.k = k;
      return;
    }
    if (sa != sb) {
      r.a = a, r.b = b, r.k = k;
      return;
    }
  }
}

// Certain sign of g over [a, b] / 2^k, or 0. With H(x) = 2^(k d) g((a + (b - a) x) / 2^k), an
// integer polynomial, |H(x) - H(0)| <= sum |H_i| for x in [0, 1].
int sign_over(const Poly& g, const Root& r) {
  const int d = g.degree();
  Coeffs h(g.c.size());
  for (int i = 0; i <= d; ++i) mul_2exp(h[i], g.c[i], r.k * unsigned(d - i));
  for (int j = 0; j < d; ++j)  // Taylor shift by a
    for (int i = d - 1; i >= j; --i) addmul(h[i], r.a, h[i + 1]);
  thread_local Int w, spread, power;
  w = r.b - r.a, spread = 0, power = 1;
  for (int i = 1; i <= d; ++i) {
    mul(power, power, w);  // w^i > 0, so spread += |h_i| w^i:
    (h[i].sign() < 0 ? submul : addmul)(spread, h[i], power);
  }
  return compare_abs(h[0], spread) > 0 ? h[0].sign() : 0;
}

}  // namespace

Poly::Poly(Coeffs coefficients) : c(std::move(coefficients)) {
  trim();
}

void Poly::trim() {
  algebra::trim(c);
}

Poly Poly::linear(const Int& at0, const Int& at1) {
  Poly p;
  p.c.resize(2);
  p.c[0] = at0;
  sub(p.c[1], at1, at0);
  p.trim();
  return p;
}

namespace {

// a + b or a - b, in place in the result.
Poly add_or_subtract(const Poly& a, const Poly& b, bool subtract) {
  static const Int zero;
  Poly out;
  out.c.resize(std::max(a.c.size(), b.c.size()));
  for (std::size_t i = 0; i < out.c.size(); ++i) {
    const Int& x = i < a.c.size() ? a.c[i] : zero;
    const Int& y = i < b.c.size() ? b.c[i] : zero;
    (subtract ? sub : add)(out.c[i], x, y);
  }
  out.trim();
  return out;
}

}  // namespace

Poly operator+(const Poly& a, const Poly& b) {
  return add_or_subtract(a, b, false);
}

Poly operator-(const Poly& a, const Poly& b) {
  return add_or_subtract(a, b, true);
}

Poly operator*(const Poly& a, const Poly& b) {
  if (a.is_zero() || b.is_zero()) return Poly();
  Poly out;
  out.c.resize(a.c.size() + b.c.size() - 1);
  for (std::size_t i = 0; i < a.c.size(); ++i)
    for (std::size_t j = 0; j < b.c.size(); ++j) addmul(out.c[i + j], a.c[i], b.c[j]);
  out.trim();
  return out;
}

Poly sum_of_products(std::initializer_list<Product> terms) {
  std::size_t n = 0;
  for (const Product& t : terms)
    if (!t.a.is_zero() && !t.b.is_zero()) n = std::max(n, t.a.c.size() + t.b.c.size() - 1);
  Poly out;
  out.c.resize(n);
  for (const Product& t : terms)
    for (std::size_t i = 0; i < t.a.c.size(); ++i)
      for (std::size_t j = 0; j < t.b.c.size(); ++j)
        (t.minus ? submul : addmul)(out.c[i + j], t.a.c[i], t.b.c[j]);
  out.trim();
  return out;
}

Poly derivative(const Poly& p) {
  Coeffs c;
  for (std::size_t i = 1; i < p.c.size(); ++i) c.push_back(p.c[i] * Int(long(i)));
  return Poly(std::move(c));
}

Poly gcd(const Poly& a0, const Poly& b0) {
  // Degrees are at most 6 here: coefficient growth without content removal stays small, and
  // removing it (integer gcds) costs more than it saves.
  Poly a = a0, b = b0;
  if (a.degree() < b.degree()) std::swap(a, b);
  while (!b.is_zero()) {
    Poly r = pseudo_remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  return primitive(std::move(a));
}

namespace {

// p / g for a g that divides p, both made primitive: by Gauss's lemma the quotient of
// primitive integer polynomials is integer, so the division is exact.
Poly exact_quotient(const Poly& p, const Poly& g0) {
  const Poly g = primitive(g0);
  Coeffs r = primitive(p).c, out(p.c.size() - g.c.size() + 1);
  for (std::size_t k = out.size(); k-- > 0;) {
    out[k] = divexact(r[k + g.c.size() - 1], g.c.back());
    for (std::size_t j = 0; j < g.c.size(); ++j) submul(r[k + j], out[k], g.c[j]);
  }
  return primitive(Poly(std::move(out)));
}

// p's Bernstein coefficients on [0, 1] scaled by d! > 0, for p != 0. p is the convex
// combination sum b_i B_i(t) of the Bernstein basis, B_i >= 0 on [0, 1] and sum B_i = 1, with
// b_i = sum_{j <= i} C(i, j) / C(d, j) a_j (Farouki & Rajan 1988, "Algorithms for polynomials
// in Bernstein form"). Scaled by d!, the b_i are the integers sum_{j <= i} C(i, j) j! (d - j)! a_j.
Coeffs bernstein(const Poly& p) {
  static const long factorial[] = {1, 1, 2, 6, 24, 120, 720};
  static const long binomial[7][7] = {{1},
                                      {1, 1},
                                      {1, 2, 1},
                                      {1, 3, 3, 1},
                                      {1, 4, 6, 4, 1},
                                      {1, 5, 10, 10, 5, 1},
                                      {1, 6, 15, 20, 15, 6, 1}};
  const int d = p.degree();
  Coeffs b(p.c.size());
  for (int i = 0; i <= d; ++i) {
    mul(b[i], p.c[0], Int(factorial[d]));
    for (int j = 1; j <= i; ++j)
      addmul(b[i], p.c[j], Int(binomial[i][j] * factorial[j] * factorial[d - j]));
  }
  return b;
}

// Root isolation on the Bernstein form by integer de Casteljau bisection (Farouki & Rajan
// 1988): on [a, a + 1] / 2^k, p is sum b_i B_i with B_i > 0 inside, b_0 and b_d its values at
// the ends (up to one positive factor). By the rule of signs, the roots inside, counted with
// multiplicity, are at most the sign variations of the b_i, of the same parity: none without
// variations; one simple root with one variation and nonzero ends (so p changes sign across).
// A zero end coefficient is a root at that end: dropping it leaves the signs of p / (t - end).
struct BernsteinIsolator {
  const Poly& s;
  Roots out;
  // Appends the roots in (a, a + 1] / 2^k, increasing; false if that takes too many halvings
  // (a multiple root or roots closer than 2^-max_k): then Sturm decides.
  bool isolate(const Coeffs& b, const Int& a, unsigned long k) {
    static constexpr unsigned long max_k = 6;
    const int d = int(b.size()) - 1;
    int changes = 0, last = 0;
    for (const Int& x : b)
      if (const int sx = x.sign(); sx != 0) changes += last != 0 && sx != last, last = sx;
    if (changes == 1 && !b[0].is_zero() && !b[d].is_zero()) {
      out.push_back(Root{&s, a, a + Int(1), k});
    } else if (changes > 0) {  // halve: the left half ends at the midpoint, the right at ours
      if (k >= max_k) return false;
      Coeffs left(b.size()), right(b.size());
      halves(b, left, right);
      const Int a2 = a << 1;
      return isolate(left, a2, k + 1) && isolate(right, a2 + Int(1), k + 1);
    }
    if (b[d].is_zero()) out.push_back(Root{&s, a + Int(1), a + Int(1), k});
    return true;
  }
  // The Bernstein coefficients on both halves, scaled by 2^d (de Casteljau at 1/2 on sums).
  static void halves(const Coeffs& b, Coeffs& left, Coeffs& right) {
    const int d = int(b.size()) - 1;
    Coeffs row = b;  // row r holds 2^r times de Casteljau's r-th row
    for (int r = 0;; ++r) {
      mul_2exp(left[r], row[0], unsigned(d - r));
      mul_2exp(right[d - r], row[d - r], unsigned(d - r));
      if (r == d) break;
      for (int i = 0; i + r < d; ++i) add(row[i], row[i], row[i + 1]);
    }
  }
};

// The roots of p in [0, 1] by Bernstein bisection, as Sturm isolation would give them (each
// exact or simple in its interval, so p needs no squarefree part); false if that does not
// finish (BernsteinIsolator).
bool unit_roots_by_bernstein(const Poly& p, Roots& out) {
  if (p.degree() < 1) return false;
  const Coeffs b = bernstein(p);
  BernsteinIsolator iso{p, {}};
  if (b[0].is_zero()) iso.out.push_back(Root{&p, Int(0), Int(0), 0});
  if (!iso.isolate(b, Int(0), 0)) return false;
  out = std::move(iso.out);
  return true;
}

// Keeps the roots in [0, 1] (increasing, from unit_roots_by_bernstein) that lie in the dyadic
// window [t0, t1] of [0, 1], exactly: a root whose interval (lo, hi) straddles t0 or t1 is
// placed by s's sign there (0: the root is that end; the sign at lo or at hi: the side).
// The unit window's Bernstein isolation is much cheaper than a Sturm sequence on the window.
void clip_to_window(const Poly& s, Roots& roots, const Dyadic& t0, const Dyadic& t1) {
  Roots kept;
  for (Root r : roots) {
    if (compare(r.hi(), t0) < 0 || compare(r.lo(), t1) > 0) continue;  // wholly outside
    if (!r.exact()) {
      if (compare(r.hi(), t0) == 0 || compare(r.lo(), t1) == 0) continue;  // open interval
      for (const bool at_start : {true, false}) {  // cut (lo, hi) at t0, then at t1
        const Dyadic& t = at_start ? t0 : t1;
        if (r.exact() || compare(r.lo(), t) >= 0 || compare(r.hi(), t) <= 0) continue;
        const int st = sign_at(s, t);
        const unsigned long k = std::max(r.k, t.k);
        const Int a = shifted(r.a, k - r.k), b = shifted(r.b, k - r.k), c = shifted(t.a, k - t.k);
        if (st == 0) {
          r = Root{&s, c, c, k};
        } else if ((st == sign_at(s, r.lo())) == at_start) {  // the root is on t's far side
          r.a = at_start ? c : a, r.b = at_start ? b : c, r.k = k;
        } else {
          r.s = nullptr;  // on the window's outside
          break;
        }
      }
      // (With t0 = t1, a cut at t0 can leave (t1, hi): outside.)
      if (!r.s || (!r.exact() && compare(r.lo(), t1) >= 0)) continue;
    }
    kept.push_back(r);
  }
  roots = std::move(kept);
}

}  // namespace

// All Bernstein coefficients of one strict sign: p has no root in [0, 1].
bool no_root_in_unit(const Poly& p) {
  if (p.is_zero() || p.c[0].is_zero()) return false;
  const int first = p.c[0].sign();
  for (const Int& b : bernstein(p))
    if (b.sign() != first) return false;
  return true;
}

Binary Binary::of(double x) {
  if (x == 0) return {};
  // IEEE 754 binary64: x = m 2^e with m the significand (the hidden bit set unless subnormal).
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = int(bits >> 52 & 0x7ff);
  std::uint64_t m = bits & ((std::uint64_t(1) << 52) - 1);
  int e = -1074;
  if (biased != 0) m |= std::uint64_t(1) << 52, e = biased - 1075;
  const int zeros = __builtin_ctzll(m);  // the fewest bits, so that the integers stay small
  m >>= zeros, e += zeros;
  return {bits >> 63 ? -long(m) : long(m), e};
}

Dyadic Dyadic::of(double x) {
  const Binary b = Binary::of(x);
  if (b.e <= 0) return {Int(b.m), unsigned(-b.e)};
  return {Int(b.m) << unsigned(b.e), 0};
}

mpq_class Dyadic::value() const {
  mpq_class q(a.to_mpz());
  mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), k);
  return q;
}

int sign_at(const Poly& p, const Dyadic& t) {
  const int d = p.degree();
  if (d < 0) return 0;
  // In place, on integers that keep their storage: Horner's v = v a + c_i 2^(k (d - i)).
  thread_local Int v, next;
  v = p.c[d];
  for (int i = d - 1; i >= 0; --i) {
    mul_2exp(next, p.c[i], t.k * unsigned(d - i));
    addmul(next, v, t.a);
    std::swap(v, next);
  }
  return v.sign();
}

bool is_unit_window(const Dyadic& t0, const Dyadic& t1) {
  return t0.a.is_zero() && t1.k == 0 && t1.a == Int(1);
}

Roots roots_in(Poly& s, const Dyadic& t0, const Dyadic& t1) {
  // The unit window: Bernstein bisection mostly finishes, without a Sturm sequence.
  Roots by_signs;
  if (unit_roots_by_bernstein(s, by_signs)) {
    if (!is_unit_window(t0, t1)) clip_to_window(s, by_signs, t0, t1);
    return by_signs;
  }
  InlineVector<Poly, kMaxDegree + 1> seq = sturm_sequence(s);
  // The last element is gcd(s, s') up to a factor (a remainder sequence): s is squarefree iff
  // it is a constant. Else the roots are those of s / gcd(s, s'), each simple.
  if (seq.back().degree() > 0) {
    s = exact_quotient(s, seq.back());
    seq = sturm_sequence(s);
  }
  Isolator iso{s, std::move(seq), {}};
  const unsigned long k = std::max(t0.k, t1.k);
  const Int a = shifted(t0.a, k - t0.k), b = shifted(t1.a, k - t1.k);
  const SturmAt fa = iso.at(a, k);
  if (fa.s == 0) iso.out.push_back(Root{&s, a, a, k});
  if (a < b) iso.isolate(a, b, k, fa, iso.at(b, k));
  return iso.out;
}

int sign_at(const Poly& g, Root& r) {
  if (g.is_zero()) return 0;
  if (r.exact()) return sign_at(g, r.lo());
  if (const int s = sign_over(g, r)) return s;  // the common case: no gcd needed
  // Narrow the interval to two adjacent doubles first: g is mostly small at the root but not
  // zero, and then the narrower interval decides without the gcd.
  if (!r.narrowed) {
    jump(r);
    r.narrowed = true;
    if (r.exact()) return sign_at(g, r.lo());
    if (const int s = sign_over(g, r)) return s;
  }
  // g vanishes at the root iff gcd(s, g) does; that gcd divides s, so its only root in
  // [lo, hi] can be ours, and then it changes sign across the interval.
  const Poly h = gcd(*r.s, g);
  if (h.degree() >= 1 && sign_at(h, r.lo()) * sign_at(h, r.hi()) < 0) return 0;
  // g(root) != 0: shrink the interval until g's sign over it is certain.
  for (;;) {
    if (!bisect_once(r)) return sign_at(g, r.lo());
    if (const int s = sign_over(g, r)) return s;
  }
}

void narrow_to_doubles(Root& r) {
  if (r.exact() || r.narrowed) return;
  jump(r);
  r.narrowed = true;
}

int compare(const Dyadic& x, const Dyadic& y) {
  const unsigned long k = std::max(x.k, y.k);
  const Int a = x.a << (k - x.k), b = y.a << (k - y.k);
  return a < b ? -1 : (b < a ? 1 : 0);
}

void refine(Root& r, unsigned long bits) {
  // width (b - a) / 2^k < 2^-bits  <=>  (b - a) 2^bits < 2^k
  while (!r.exact() && shifted(r.b - r.a, bits) >= shifted(Int(1), r.k))
    if (!bisect_once(r)) break;
}

}  // namespace fdh::exact::algebra
