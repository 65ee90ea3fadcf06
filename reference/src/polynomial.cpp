#include "polynomial.hpp"

#include <cstdlib>
#include <utility>

namespace fdh::exact::algebra {
namespace {

void trim(std::vector<mpq_class>& c) {
  while (!c.empty() && sgn(c.back()) == 0) c.pop_back();
}

Poly monic(Poly p) {
  if (p.is_zero()) return p;
  const mpq_class lead = p.c.back();
  for (mpq_class& x : p.c) x /= lead;
  return p;
}

// The Sturm sequence of a squarefree s: s, s', then negated remainders down to a constant.
std::vector<Poly> sturm_sequence(const Poly& s) {
  std::vector<Poly> seq{s, derivative(s)};
  while (!seq.back().is_zero() && seq.back().degree() > 0) {
    Poly r = remainder(seq[seq.size() - 2], seq.back());
    if (r.is_zero()) break;
    for (mpq_class& x : r.c) x = -x;
    seq.push_back(std::move(r));
  }
  return seq;
}

// Sign variations of the sequence at t, zeros dropped. For squarefree s, V(a) - V(b) is the
// number of distinct roots in (a, b] (Sturm's theorem with the half-open convention).
int variations(const std::vector<Poly>& seq, const mpq_class& t) {
  int v = 0, last = 0;
  for (const Poly& p : seq) {
    const int s = p.sign_at(t);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}

struct Isolator {
  const Poly& s;
  std::vector<Poly> seq;
  std::vector<Root> out;

  int count(const mpq_class& a, const mpq_class& b) const {
    return variations(seq, a) - variations(seq, b);
  }

  // Appends the roots in (a, b], in order.
  void isolate(mpq_class a, mpq_class b) {
    const int n = count(a, b);
    if (n == 0) return;
    if (n > 1) {
      const mpq_class m = (a + b) / 2;
      isolate(a, m);
      isolate(m, b);
      return;
    }
    if (s.sign_at(b) == 0) {
      out.push_back(Root{&s, b, b});
      return;
    }
    // One root in (a, b). Move a off a root of s so that s changes sign across (a, b).
    while (s.sign_at(a) == 0) {
      const mpq_class m = (a + b) / 2;
      if (s.sign_at(m) == 0) {
        out.push_back(Root{&s, m, m});
        return;
      }
      (count(m, b) == 1 ? a : b) = m;
    }
    out.push_back(Root{&s, a, b});
  }
};

// Coefficients of g(m + x) in x: the Taylor expansion at m, by repeated synthetic division.
std::vector<mpq_class> taylor_at(const Poly& g, const mpq_class& m) {
  std::vector<mpq_class> a = g.c;
  const int n = int(a.size());
  for (int k = 0; k < n; ++k)
    for (int i = n - 2; i >= k; --i) a[i] += m * a[i + 1];
  return a;
}

bool bisect_once(Root& r) {
  const mpq_class m = (r.lo + r.hi) / 2;
  const int sm = r.s->sign_at(m);
  if (sm == 0) {
    r.lo = r.hi = m;
    return false;
  }
  (r.s->sign_at(r.lo) == sm ? r.lo : r.hi) = m;
  return true;
}

}  // namespace

Poly::Poly(std::vector<mpq_class> coefficients) : c(std::move(coefficients)) {
  trim(c);
}

Poly Poly::linear(const mpq_class& at0, const mpq_class& at1) {
  return Poly({at0, at1 - at0});
}

mpq_class Poly::operator()(const mpq_class& t) const {
  mpq_class v = 0;
  for (std::size_t i = c.size(); i-- > 0;) v = v * t + c[i];
  return v;
}

Poly operator+(const Poly& a, const Poly& b) {
  std::vector<mpq_class> c(std::max(a.c.size(), b.c.size()));
  for (std::size_t i = 0; i < a.c.size(); ++i) c[i] += a.c[i];
  for (std::size_t i = 0; i < b.c.size(); ++i) c[i] += b.c[i];
  return Poly(std::move(c));
}

Poly operator-(const Poly& a, const Poly& b) {
  std::vector<mpq_class> c(std::max(a.c.size(), b.c.size()));
  for (std::size_t i = 0; i < a.c.size(); ++i) c[i] += a.c[i];
  for (std::size_t i = 0; i < b.c.size(); ++i) c[i] -= b.c[i];
  return Poly(std::move(c));
}

Poly operator*(const Poly& a, const Poly& b) {
  if (a.is_zero() || b.is_zero()) return Poly();
  std::vector<mpq_class> c(a.c.size() + b.c.size() - 1);
  for (std::size_t i = 0; i < a.c.size(); ++i)
    for (std::size_t j = 0; j < b.c.size(); ++j) c[i + j] += a.c[i] * b.c[j];
  return Poly(std::move(c));
}

Poly derivative(const Poly& p) {
  std::vector<mpq_class> c;
  for (std::size_t i = 1; i < p.c.size(); ++i) c.push_back(p.c[i] * int(i));
  return Poly(std::move(c));
}

namespace {
// Long division: a = q b + r with deg r < deg b.
std::pair<Poly, Poly> divide(const Poly& a, const Poly& b) {
  std::vector<mpq_class> r = a.c;
  std::vector<mpq_class> q(a.c.size() >= b.c.size() ? a.c.size() - b.c.size() + 1 : 0);
  for (std::size_t k = q.size(); k-- > 0;) {
    const mpq_class f = r[k + b.c.size() - 1] / b.c.back();
    q[k] = f;
    for (std::size_t j = 0; j < b.c.size(); ++j) r[k + j] -= f * b.c[j];
  }
  return {Poly(std::move(q)), Poly(std::move(r))};
}
}  // namespace

Poly remainder(const Poly& a, const Poly& b) {
  return divide(a, b).second;
}
Poly quotient(const Poly& a, const Poly& b) {
  return divide(a, b).first;
}

Poly gcd(Poly a, Poly b) {
  while (!b.is_zero()) {
    Poly r = remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  return monic(std::move(a));
}

Poly squarefree(const Poly& p) {
  const Poly g = gcd(p, derivative(p));
  return g.degree() <= 0 ? monic(p) : monic(quotient(p, g));
}

std::vector<Root> roots_in(const Poly& s, const mpq_class& t0, const mpq_class& t1) {
  Isolator iso{s, sturm_sequence(s), {}};
  if (s.sign_at(t0) == 0) iso.out.push_back(Root{&s, t0, t0});
  if (t0 < t1) iso.isolate(t0, t1);
  return iso.out;
}

int sign_at(const Poly& g, Root& r) {
  if (r.rational()) return g.sign_at(r.lo);
  // g vanishes at the root iff gcd(s, g) does; that gcd divides s, so its only root in
  // [lo, hi] can be ours, and then it changes sign across the interval.
  const Poly h = gcd(*r.s, g);
  if (h.degree() >= 1 && h.sign_at(r.lo) * h.sign_at(r.hi) < 0) return 0;
  // g(root) != 0: shrink the interval until |g(m)| beats the Taylor bound of g's variation.
  for (;;) {
    const mpq_class m = (r.lo + r.hi) / 2, rad = (r.hi - r.lo) / 2;
    const std::vector<mpq_class> d = taylor_at(g, m);
    mpq_class spread = 0, power = 1;
    for (std::size_t k = 1; k < d.size(); ++k) {
      power *= rad;
      spread += abs(d[k]) * power;
    }
    if (d.empty()) return 0;
    if (abs(d[0]) > spread) return sgn(d[0]);
    if (!bisect_once(r)) return g.sign_at(r.lo);
  }
}

void refine(Root& r, const mpq_class& width) {
  while (!r.rational() && r.hi - r.lo >= width)
    if (!bisect_once(r)) break;
}

}  // namespace fdh::exact::algebra
