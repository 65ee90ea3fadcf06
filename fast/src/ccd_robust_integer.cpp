#include "ccd_robust_integer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <optional>

#include "ccd_robust_conditions.hpp"
#include "checked_int.hpp"
#include "motion.hpp"
#include "small_poly.hpp"

namespace fdh {
namespace {

using small_poly::Fraction;
using small_poly::Poly;
using small_poly::Root;

// ---- The query on integers: every coordinate times one power of two 2^s, the smallest that
// makes them all integers, each then below 2^kMaxIntegerBits in size (else false). Read from the
// bits: x = m 2^e with m an integer of at most 53 bits.
bool integer_coordinates(const Query& q, std::int64_t c[8][3]) {
  std::uint64_t m[24];
  int e[24], low = 1 << 20;  // the least exponent of a set bit
  for (int i = 0; i < 24; ++i) {
    const Vec3& v = q.x[i / 3];
    const double x = i % 3 == 0 ? v.x : (i % 3 == 1 ? v.y : v.z);
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = int(bits >> 52) & 0x7ff;
    if (biased == 0x7ff) return false;  // infinite or NaN
    m[i] = (bits & ((std::uint64_t(1) << 52) - 1)) | (biased != 0 ? std::uint64_t(1) << 52 : 0);
    e[i] = (biased != 0 ? biased : 1) - 1075;
    if (m[i] != 0) low = std::min(low, e[i] + __builtin_ctzll(m[i]));
  }
  for (int i = 0; i < 24; ++i) {
    std::int64_t value = 0;
    if (m[i] != 0) {
      const int tz = __builtin_ctzll(m[i]), shift = e[i] + tz - low;  // >= 0
      const std::uint64_t odd = m[i] >> tz;
      if (shift + 64 - __builtin_clzll(odd) > kMaxIntegerBits) return false;
      value = std::int64_t(odd << shift);
    }
    const Vec3& v = q.x[i / 3];
    const double x = i % 3 == 0 ? v.x : (i % 3 == 1 ? v.y : v.z);
    c[i / 3][i % 3] = x < 0 ? -value : value;
  }
  return true;
}

// A vector of polynomials in t (a moving point), or of integers (a point at an exact time p / q,
// times q).
// The motion's vectors (motion.hpp), here of exact polynomials and integers.
template <class T>
using V = motion::V3<T>;
template <class T>
bool is_zero(const V<T>& v) {
  return v.x.is_zero() && v.y.is_zero() && v.z.is_zero();
}
using PV = V<Poly>;
using IV = V<Int128>;

// A moving coordinate c0 + c1 t of the query, or a difference of two: below 2^kMaxIntegerBits,
// |c0| < 2^33 and |c1| < 2^34, so that a product of three and a sum of a few such products stay
// far inside 128 bits and are formed unchecked (the stage's hot loop).
static_assert(kMaxIntegerBits <= 32);
struct Lin {
  std::int64_t c0 = 0, c1 = 0;
  bool is_zero() const { return c0 == 0 && c1 == 0; }
  Lin operator-(const Lin& o) const { return {c0 - o.c0, c1 - o.c1}; }
  Poly poly() const { return {{c0, c1, 0, 0}}; }
};
using LV = V<Lin>;

// a b - c d, coefficients < 2^70.
Poly products(const Lin& a, const Lin& b, const Lin& c, const Lin& d) {
  using W = __int128;
  return {{Int128::of(W(a.c0) * b.c0 - W(c.c0) * d.c0),
           Int128::of(W(a.c0) * b.c1 + W(a.c1) * b.c0 - W(c.c0) * d.c1 - W(c.c1) * d.c0),
           Int128::of(W(a.c1) * b.c1 - W(c.c1) * d.c1), 0}};
}
PV cross(const LV& a, const LV& b) {
  return {products(a.y, b.z, a.z, b.y), products(a.z, b.x, a.x, b.z), products(a.x, b.y, a.y, b.x)};
}
Poly dot(const LV& a, const LV& b) {  // coefficients < 2^71
  const Lin zero;
  return products(a.x, b.x, zero, zero) + products(a.y, b.y, zero, zero) +
         products(a.z, b.z, zero, zero);
}
// A moving vector times one of cross(), coefficients < 2^109.
Poly dot(const LV& a, const PV& b) {
  __int128 r[4] = {0, 0, 0, 0};
  const Lin* l[3] = {&a.x, &a.y, &a.z};
  const Poly* q[3] = {&b.x, &b.y, &b.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r[j] += l[i]->c0 * q[i]->c[j].value();
      r[j + 1] += l[i]->c1 * q[i]->c[j].value();
    }
  return {{Int128::of(r[0]), Int128::of(r[1]), Int128::of(r[2]), Int128::of(r[3])}};
}

// ---- Contact at an exact time, given coplanarity: reference/'s exact_ccd.cpp on integers.

// Closed segment membership, degenerate segments included.
bool on_segment(const IV& p, const IV& a, const IV& b) {
  const IV pa = p - a;
  return is_zero(cross(pa, b - a)) && dot(pa, p - b).sign() <= 0;
}

// p in the closed triangle abc (a zero-area one is the union of its edges).
bool inside(const IV& p, const IV& a, const IV& b, const IV& c) {
  const IV n = cross(b - a, c - a);
  if (is_zero(n)) return on_segment(p, a, b) || on_segment(p, b, c) || on_segment(p, c, a);
  const IV ap = a - p;
  return dot(n, cross(b - p, c - p)).sign() >= 0 && dot(n, cross(c - p, ap)).sign() >= 0 &&
         dot(n, cross(ap, b - p)).sign() >= 0;
}

// The closed segments [a0, a1] and [b0, b1] meet.
bool meet(const IV& a0, const IV& a1, const IV& b0, const IV& b1) {
  const IV ea = a1 - a0, eb = b1 - b0, m = cross(ea, eb);
  if (is_zero(m))
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
    for (int i = 0; i < 4; ++i)
      x_[i] = {Lin{c[i][0], c[i + 4][0] - c[i][0]}, Lin{c[i][1], c[i + 4][1] - c[i][1]},
               Lin{c[i][2], c[i + 4][2] - c[i][2]}};
    std::memcpy(c_, c, sizeof c_);
  }
  IntegerToi run();

 private:
  IV at(int i, const Fraction& t) const {  // point i at t, times t.q
    const Int128 r = t.q - t.p;
    const auto lerp = [&](int j) { return Int128(c_[i][j]) * r + Int128(c_[i + 4][j]) * t.p; };
    return {lerp(0), lerp(1), lerp(2)};
  }
  bool touch(const Fraction& t) const {  // at a coplanar time
    const IV p = at(0, t), a = at(1, t), b = at(2, t), c = at(3, t);
    return q_.kind == QueryKind::VertexFace ? inside(p, a, b, c) : meet(p, a, b, c);
  }
  void roots_of(const Poly& f);
  bool isolate(const Piece& p);
  bool open_root(Piece p);
  std::optional<bool> bracketed_root(const Piece& p);
  double rough_root(double lo, double hi, int s_lo) const;
  std::optional<bool> conditions_over(double lo, double hi);
  bool exact_root(const Fraction& t);
  void coplanar_throughout();
  std::optional<Root> point_edge(int p, int a, int b) const;
  std::optional<Root> point_point(int p, int a) const;
  bool apart(int p, int a, int b) const;
  void candidate(const Root& r);

  const Query& q_;
  bool want_time_;
  LV x_[4];
  Poly f_;                // the coplanarity cubic
  std::int64_t c_[8][3];  // the coordinates: point i at t = 0, point i + 4 at t = 1
  bool found_ = false, undecided_ = false, exact_ = false;
  Fraction when_;  // with exact_, the earliest contact
  // Coplanar throughout: the contacts found at irrational times (one per vertex-edge pair).
  Root irrational_[4];
  int irrationals_ = 0;
};

IntegerToi Search::run() {
  const LV& p = x_[0];
  f_ = q_.kind == QueryKind::VertexFace ? dot(x_[1] - p, cross(x_[2] - p, x_[3] - p))
                                        : dot(x_[1] - p, cross(x_[2] - p, x_[3] - x_[2]));
  if (f_.is_zero())
    coplanar_throughout();
  else
    roots_of(f_);
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

// The conditions over [lo, hi] by intervals (as the subdivision's contact_at_root), given one
// root of f there: some certainly < 0, none (false); all > 0, a contact (true); else neither.
std::optional<bool> Search::conditions_over(double lo, double hi) {
  using namespace ccd_conditions;
  const Signs s = certain_signs(conditions_at(q_, Interval{lo, hi}));
  if (s.out) return false;
  if (s.inside) return found_ = true;  // somewhere in (lo, hi): not an exact time
  return std::nullopt;
}

// f's root in (lo, hi), where its sign is s_lo just above lo, roughly: Newton steps in doubles
// kept inside a bracket that is halved instead when a step leaves it. Never part of a verdict.
double Search::rough_root(double lo, double hi, int s_lo) const {
  double c[4];
  for (int i = 0; i < 4; ++i) c[i] = f_.c[i].approx();
  double u = lo + (hi - lo) / 2;
  for (int i = 0; i < 10; ++i) {
    const double v = ((c[3] * u + c[2]) * u + c[1]) * u + c[0];
    const double slope = (3 * c[3] * u + 2 * c[2]) * u + c[1];
    ((v > 0) == (s_lo > 0) ? lo : hi) = u;
    const double next = u - v / slope;
    u = next > lo && next < hi ? next : lo + (hi - lo) / 2;  // a NaN step halves too
  }
  return u;
}

// The root in p bracketed by two neighbouring multiples of 2^-kBracketBits inside p around the
// rough root, by f's exact signs there (those just inside p at its ends), then settled over the
// bracket by intervals: true or false where that decides, nullopt where it does not (or the
// guess did not bracket, or a sign would overflow).
std::optional<bool> Search::bracketed_root(const Piece& p) {
  constexpr int kBracketBits = 24;
  if (p.k > kBracketBits) return std::nullopt;
  int s_lo = 0, s_hi = 0;
  for (const Int128& c : p.b) s_hi = c.is_zero() ? s_hi : c.sign(), s_lo = s_lo != 0 ? s_lo : s_hi;
  const double unit = 1 / double(std::int64_t(1) << p.k), scale = double(1 << kBracketBits);
  const double u = rough_root(double(p.a) * unit, double(p.a + 1) * unit, s_lo);
  const std::int64_t first = p.a << (kBracketBits - p.k),
                     last = ((p.a + 1) << (kBracketBits - p.k)) - 1;
  const std::int64_t a = std::clamp(std::int64_t(std::floor(u * scale)), first, last);
  const Fraction t0{a, std::int64_t(1) << kBracketBits}, t1{a + 1, t0.q};
  int s0 = s_lo, s1 = s_hi;
  try {
    if (a != first) s0 = small_poly::sign_at(f_, t0);
    if (a != last) s1 = small_poly::sign_at(f_, t1);
  } catch (const IntegerOverflow&) {
    return std::nullopt;
  }
  if (s0 == 0) return exact_root(t0);
  if (s1 == 0) return exact_root(t1);
  if (s0 == s1) return std::nullopt;
  if (std::optional<bool> r = conditions_over(double(a) / scale, double(a + 1) / scale)) return r;
  undecided_ = true;  // a condition about 0 at the root: deeper would not do either
  return false;
}

// One simple root inside p: bracketed (above), else halvings toward the root, the intervals
// over the piece every 8; a halving that lands on the root makes it exact.
bool Search::open_root(Piece p) {
  if (const std::optional<bool> r = bracketed_root(p)) return *r;
  for (int round = 0; round < 4; ++round) {
    const double unit = 1 / double(std::int64_t(1) << p.k);  // exact: a power of two
    if (const std::optional<bool> r = conditions_over(double(p.a) * unit, double(p.a + 1) * unit))
      return *r;
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
  const LV d = x_[p] - x_[a];
  if (is_zero(d)) return at_start();
  const Poly x = d.x.poly(), y = d.y.poly(), z = d.z.poly();
  return first_common_root({&x, &y, &z}, [](const Root&) { return true; });
}

// Whether the boxes that p and the segment ab sweep over the step are apart on some axis: the
// segment at any time lies in the box of its ends at both times, so p then never meets it.
bool Search::apart(int p, int a, int b) const {
  for (int j = 0; j < 3; ++j) {
    const std::int64_t p_lo = std::min(c_[p][j], c_[p + 4][j]),
                       p_hi = std::max(c_[p][j], c_[p + 4][j]);
    const std::int64_t s_lo = std::min({c_[a][j], c_[a + 4][j], c_[b][j], c_[b + 4][j]});
    const std::int64_t s_hi = std::max({c_[a][j], c_[a + 4][j], c_[b][j], c_[b + 4][j]});
    if (p_hi < s_lo || s_hi < p_lo) return true;
  }
  return false;
}

// Point p on the moving segment ab (reference/'s Search::point_edge): where p - a and b - a are
// not parallel throughout, at the common roots of their cross product w with p between a and b
// ((p - a).(p - b) <= 0); else at the start, or where p meets an end.
std::optional<Root> Search::point_edge(int p, int a, int b) const {
  if (apart(p, a, b)) return std::nullopt;
  const LV pa = x_[p] - x_[a];
  const PV w = cross(pa, x_[b] - x_[a]);
  const Poly h = dot(pa, x_[p] - x_[b]);
  if (!is_zero(w))
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
