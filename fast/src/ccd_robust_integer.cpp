#include "ccd_robust_integer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>

#include "ccd_robust_conditions.hpp"
#include "checked_int.hpp"
#include "small_poly.hpp"

namespace fdh {
namespace {

using small_poly::Fraction;
using small_poly::Poly;
using small_poly::Root;

// ---- The query on integers: every coordinate times one power of two 2^s, the smallest that
// makes them all integers, each then below 2^kMaxIntegerBits in size (else false).
bool integer_coordinates(const Query& q, std::int64_t c[8][3]) {
  int scale = -2000;
  for (const Vec3& v : q.x)
    for (const double x : {v.x, v.y, v.z}) {
      if (x == 0) continue;
      if (!std::isfinite(x)) return false;
      int e;
      const double f = std::frexp(x, &e);  // x = f 2^e = m 2^(e - 53), m an integer
      const auto m = static_cast<std::int64_t>(std::ldexp(std::fabs(f), 53));
      scale = std::max(scale, 53 - e - __builtin_ctzll(static_cast<std::uint64_t>(m)));
    }
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 3; ++j) {
      const double x = j == 0 ? q.x[i].x : (j == 1 ? q.x[i].y : q.x[i].z);
      const double s = std::ldexp(x, scale);  // exact: an integer below 2^32, or refused
      if (!(std::fabs(s) < std::ldexp(1.0, kMaxIntegerBits))) return false;
      c[i][j] = static_cast<std::int64_t>(s);
    }
  return true;
}

// A vector of polynomials in t (a moving point), or of integers (a point at an exact time p / q,
// times q).
template <class T>
struct V {
  T x, y, z;
  bool is_zero() const { return x.is_zero() && y.is_zero() && z.is_zero(); }
};
template <class T>
V<T> operator-(const V<T>& a, const V<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
V<T> cross(const V<T>& a, const V<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
T dot(const V<T>& a, const V<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
using PV = V<Poly>;
using IV = V<Int128>;

// ---- Contact at an exact time, given coplanarity: reference/'s exact_ccd.cpp on integers.

// Closed segment membership, degenerate segments included.
bool on_segment(const IV& p, const IV& a, const IV& b) {
  const IV pa = p - a;
  return cross(pa, b - a).is_zero() && dot(pa, p - b).sign() <= 0;
}

// p in the closed triangle abc (a zero-area one is the union of its edges).
bool inside(const IV& p, const IV& a, const IV& b, const IV& c) {
  const IV n = cross(b - a, c - a);
  if (n.is_zero()) return on_segment(p, a, b) || on_segment(p, b, c) || on_segment(p, c, a);
  const IV ap = a - p;
  return dot(n, cross(b - p, c - p)).sign() >= 0 && dot(n, cross(c - p, ap)).sign() >= 0 &&
         dot(n, cross(ap, b - p)).sign() >= 0;
}

// The closed segments [a0, a1] and [b0, b1] meet.
bool meet(const IV& a0, const IV& a1, const IV& b0, const IV& b1) {
  const IV ea = a1 - a0, eb = b1 - b0, m = cross(ea, eb);
  if (m.is_zero())
    return on_segment(a0, b0, b1) || on_segment(a1, b0, b1) || on_segment(b0, a0, a1) ||
           on_segment(b1, a0, a1);
  const Int128 s = dot(cross(b0 - a0, eb), m), u = dot(cross(b0 - a0, ea), m), mm = dot(m, m);
  return s.sign() >= 0 && u.sign() >= 0 && (mm - s).sign() >= 0 && (mm - u).sign() >= 0;
}

// f's Bernstein coefficients on [a / 2^k, (a + 1) / 2^k], times a positive integer.
struct Piece {
  Int128 b[4];
  std::int64_t a = 0;
  int k = 0;
};

// Sign variations, zeros skipped: by Descartes' rule (on the Bernstein form) a bound on the
// roots in the open piece, with their count of the same parity.
int variations(const Piece& p) {
  int v = 0, prev = 0;
  for (const Int128& c : p.b)
    if (const int s = c.sign(); s != 0) {
      if (prev != 0 && s != prev) ++v;
      prev = s;
    }
  return v;
}

// Divides by the common power of two, so that the coefficients grow by at most 3 bits a split.
void reduce(Piece& p) {
  int z = 128;
  for (const Int128& c : p.b) z = std::min(z, c.trailing_zeros());
  if (z > 0 && z < 128)
    for (Int128& c : p.b) c = c.shifted_right(z);
}

// de Casteljau at the middle, times 8: the left half ends, and the right begins, with f's value
// at the middle (times 8^(k + 1) over the scale).
void split(const Piece& p, Piece& left, Piece& right) {
  const Int128* b = p.b;
  const Int128 m = b[0] + Int128(3) * (b[1] + b[2]) + b[3];
  left = {{Int128(8) * b[0], Int128(4) * (b[0] + b[1]),
           Int128(2) * (b[0] + Int128(2) * b[1] + b[2]), m},
          2 * p.a,
          p.k + 1};
  right = {{m, Int128(2) * (b[1] + Int128(2) * b[2] + b[3]), Int128(4) * (b[2] + b[3]),
            Int128(8) * b[3]},
           2 * p.a + 1,
           p.k + 1};
  reduce(left), reduce(right);
}

Fraction middle(const Piece& p) {
  return {Int128(2 * p.a + 1), Int128(std::int64_t(1) << (p.k + 1))};
}

// The fraction t in [0, 1] as doubles around it, at most one apart (t itself when a double).
bool enclose(const Fraction& t, double& lo, double& hi) {
  if (!t.p.fits_double() || !t.q.fits_double()) return false;
  const double p = t.p.approx(), q = t.q.approx(), d = p / q;  // correctly rounded
  const double residual = std::fma(-d, q, p);                  // p - d q, exactly
  lo = residual < 0 ? std::nextafter(d, 0.0) : d;
  hi = residual > 0 ? std::nextafter(d, 2.0) : d;
  return true;
}

// The deepest piece: a < 2^52, so its ends are doubles.
constexpr int kMaxDepth = 52;
// Isolation stops subdividing here: several roots this close, or a multiple root off the dyadic
// times, are left to the fallback.
constexpr int kMaxIsolationDepth = 20;

// The search, in time order, for the first contact: at f's roots where f is not identically 0,
// else (coplanar throughout) at the start or where a vertex meets an edge's line on the edge.
class Search {
 public:
  Search(const Query& q, const std::int64_t c[8][3], bool want_time)
      : q_(q), want_time_(want_time) {
    for (int i = 0; i < 4; ++i) {
      x_[i] = {Poly::linear(c[i][0], c[i + 4][0]), Poly::linear(c[i][1], c[i + 4][1]),
               Poly::linear(c[i][2], c[i + 4][2])};
      for (int j = 0; j < 3; ++j) c0_[i][j] = c[i][j], c1_[i][j] = c[i + 4][j];
    }
  }
  IntegerToi run();

 private:
  IV at(int i, const Fraction& t) const {  // point i at t, times t.q
    const Int128 r = t.q - t.p;
    return {c0_[i][0] * r + c1_[i][0] * t.p, c0_[i][1] * r + c1_[i][1] * t.p,
            c0_[i][2] * r + c1_[i][2] * t.p};
  }
  bool touch(const Fraction& t) const {  // at a coplanar time
    const IV p = at(0, t), a = at(1, t), b = at(2, t), c = at(3, t);
    return q_.kind == QueryKind::VertexFace ? inside(p, a, b, c) : meet(p, a, b, c);
  }
  void roots_of(const Poly& f);
  bool isolate(const Piece& p);
  bool open_root(Piece p);
  bool exact_root(const Fraction& t);
  void coplanar_throughout();
  std::optional<Root> point_edge(int p, int a, int b) const;
  std::optional<Root> point_point(int p, int a) const;
  void candidate(const Root& r);

  const Query& q_;
  bool want_time_;
  PV x_[4];
  Int128 c0_[4][3], c1_[4][3];
  bool found_ = false, undecided_ = false, exact_ = false;
  Fraction when_;  // with exact_, the earliest contact
  // Coplanar throughout: the contacts found at irrational times (one per vertex-edge pair).
  Root irrational_[4];
  int irrationals_ = 0;
};

IntegerToi Search::run() {
  const PV& p = x_[0];
  const Poly f = q_.kind == QueryKind::VertexFace ? dot(x_[1] - p, cross(x_[2] - p, x_[3] - p))
                                                  : dot(x_[1] - p, cross(x_[2] - p, x_[3] - x_[2]));
  if (f.is_zero())
    coplanar_throughout();
  else
    roots_of(f);
  IntegerToi r;
  r.verdict = found_ ? Filtered::Yes : (undecided_ ? Filtered::Uncertain : Filtered::No);
  if (found_ && exact_ && want_time_) r.exact = enclose(when_, r.t_lo, r.t_hi);
  return r;
}

// A contact at f's root t, an exact time: the first one found, so the earliest unless a root
// before it was left undecided.
bool Search::exact_root(const Fraction& t) {
  if (!touch(t)) return false;
  found_ = true;
  exact_ = !undecided_, when_ = t;
  return true;
}

// f's Bernstein coefficients on [0, 1] from its monomial ones, times 3 (binomial(3, i) b_i are
// integers); its roots at 0, inside and at 1, in that order.
void Search::roots_of(const Poly& f) {
  const Int128* c = f.c;
  Piece p{{Int128(3) * c[0], Int128(3) * c[0] + c[1], Int128(3) * c[0] + Int128(2) * c[1] + c[2],
           Int128(3) * (c[0] + c[1] + c[2] + c[3])}};
  if (p.b[0].is_zero() && exact_root({0, 1})) return;
  if (isolate(p)) return;
  if (p.b[3].is_zero()) exact_root({1, 1});
}

// True when a contact is found in p or at a split point inside it (time order: left, middle,
// right).
bool Search::isolate(const Piece& p) {
  const int v = variations(p);
  if (v == 0) return false;
  if (v == 1) return open_root(p);
  if (p.k == kMaxIsolationDepth) {
    undecided_ = true;
    return false;
  }
  Piece left, right;
  split(p, left, right);
  if (isolate(left)) return true;
  if (left.b[3].is_zero() && exact_root(middle(p))) return true;
  return isolate(right);
}

// One simple root inside p: the conditions over the piece by intervals (as the subdivision's
// contact_at_root), the piece halved toward the root in between, 8 times a round; a halving
// that lands on the root makes it exact.
bool Search::open_root(Piece p) {
  using namespace ccd_conditions;
  for (int round = 0; round < 4; ++round) {
    const double lo = std::ldexp(double(p.a), -p.k), hi = std::ldexp(double(p.a + 1), -p.k);
    const Signs s = certain_signs(conditions_at(q_, Interval{lo, hi}));
    if (s.out) return false;
    if (s.inside) return found_ = true;  // somewhere in (lo, hi): not an exact time
    for (int i = 0; i < 8 && p.k < kMaxDepth; ++i) {
      Piece left, right;
      split(p, left, right);
      if (left.b[3].is_zero()) return exact_root(middle(p));
      p = variations(left) == 1 ? left : right;
    }
  }
  undecided_ = true;
  return false;
}

// The first common root in [0, 1] of the polynomials (degree <= 2, not all 0) where ok holds:
// the roots of the one of lowest degree where every other vanishes.
template <class Ok>
std::optional<Root> first_common_root(std::initializer_list<const Poly*> polys, Ok ok) {
  const Poly* base = nullptr;
  for (const Poly* g : polys)
    if (!g->is_zero() && (base == nullptr || g->degree() < base->degree())) base = g;
  Root roots[2];
  const int n = base == nullptr ? 0 : small_poly::roots_in_unit(*base, roots);
  for (int i = 0; i < n; ++i) {
    bool common = true;
    for (const Poly* g : polys)
      common = common && (g == base || small_poly::sign_at(*g, roots[i]) == 0);
    if (common && ok(roots[i])) return roots[i];
  }
  return std::nullopt;
}

Root at_start() {
  return Root{true, {0, 1}, {}, 0};
}

std::optional<Root> Search::point_point(int p, int a) const {
  const PV d = x_[p] - x_[a];
  if (d.is_zero()) return at_start();
  return first_common_root({&d.x, &d.y, &d.z}, [](const Root&) { return true; });
}

// Point p on the moving segment ab (reference/'s Search::point_edge): where p - a and b - a are
// not parallel throughout, at the common roots of their cross product w with p between a and b
// ((p - a).(p - b) <= 0); else at the start, or where p meets an end.
std::optional<Root> Search::point_edge(int p, int a, int b) const {
  const PV pa = x_[p] - x_[a], w = cross(pa, x_[b] - x_[a]);
  const Poly h = dot(pa, x_[p] - x_[b]);
  if (!w.is_zero())
    return first_common_root({&w.x, &w.y, &w.z},
                             [&h](const Root& r) { return small_poly::sign_at(h, r) <= 0; });
  if (small_poly::sign_at(h, Fraction{0, 1}) <= 0) return at_start();
  const std::optional<Root> ra = point_point(p, a), rb = point_point(p, b);
  if (!ra || !rb) return ra ? ra : rb;
  return small_poly::compare(ra->t, rb->t) <= 0 ? ra : rb;  // both rational: linear roots
}

void Search::candidate(const Root& r) {
  if (!r.rational) {
    irrational_[irrationals_++] = r;
  } else if (!exact_ || small_poly::compare(r.t, when_) < 0) {
    when_ = r.t;
    exact_ = true;
  }
  found_ = true;
}

// f identically 0: a first contact after the start puts a vertex on an edge, since one inside
// a face (or a proper crossing of edges) was there a moment earlier too.
void Search::coplanar_throughout() {
  if (touch({0, 1})) {
    found_ = exact_ = true;
    return;  // when_ is 0
  }
  static constexpr int kVertexFace[3][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}};
  static constexpr int kEdgeEdge[4][3] = {{0, 2, 3}, {1, 2, 3}, {2, 0, 1}, {3, 0, 1}};
  const bool vf = q_.kind == QueryKind::VertexFace;
  for (int i = 0; i < (vf ? 3 : 4); ++i) {
    const int* e = vf ? kVertexFace[i] : kEdgeEdge[i];
    if (const std::optional<Root> r = point_edge(e[0], e[1], e[2])) candidate(*r);
    if (found_ && !want_time_) return;
  }
  // The earliest is a fraction only if every irrational candidate comes after the earliest one.
  for (int i = 0; i < irrationals_ && exact_; ++i)
    exact_ = small_poly::compare(irrational_[i], when_) > 0;
}

}  // namespace

IntegerToi robust_ccd_integer(const Query& q, bool want_time) {
  std::int64_t c[8][3];
  if (!integer_coordinates(q, c)) return {};
  try {
    Search search(q, c, want_time);
    return search.run();
  } catch (const IntegerOverflow&) {
    return {};
  }
}

}  // namespace fdh
