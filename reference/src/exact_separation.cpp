// Minimum separation, exactly (docs/methods.md, "Minimum separation"). dist <= δ is the union
// of pieces, one per closest feature pair, each a conjunction of sign conditions on integer
// polynomials in t of degree <= 6:
//   point p vs triangle abc: each vertex (|p - a|^2 <= δ^2), each edge as a point-edge piece,
//     and the face: n = (b - a) x (c - a) != 0, the projection of p inside (three degree-4
//     signs), ((p - a).n)^2 <= δ^2 |n|^2;
//   point p vs edge [a, b], e = b - a, w = p - a: |e|^2 > 0, 0 <= e.w <= |e|^2,
//     |e x w|^2 <= δ^2 |e|^2 (the distance to the line, the foot inside);
//   edge vs edge: the four end-end pieces, the four end-edge pieces, and the interior:
//     n = d1 x d2 != 0, both closest-point parameters in [0, 1], (r.n)^2 <= δ^2 |n|^2.
// Every piece implies dist <= δ and every time with dist <= δ lies in some piece, so their union
// is {t : dist(t) <= δ}, a closed set: t*_δ is the least of the pieces' infima. A piece's
// infimum is t0 or a root of one of its polynomials: the first such point where the piece holds,
// or holds just after (the sign just after a point is that of the first derivative not zero
// there). The candidates go to earliest_contact.hpp like the contact search's.
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <vector>

#include "earliest_contact.hpp"
#include "moving_points.hpp"
#include "polynomial.hpp"
#include "separation.hpp"

namespace fdh::exact {
namespace {

using algebra::Dyadic;
using algebra::Int;
using algebra::Poly;
using algebra::Root;

// A sign condition on a polynomial in t: p >= 0, or p > 0 if strict.
struct Condition {
  Poly p;
  bool strict = false;
};
using Piece = algebra::InlineVector<Condition, 6>;

// δ^2 in the coordinates' scale, exactly: m 2^e with m > 0.
struct SquaredDistance {
  Int m;
  long e = 0;
};

Poly constant(const Int& x) {
  return Poly(algebra::Coeffs{x});
}

Poly times(const Poly& p, const Int& f) {
  Poly out = p;
  for (Int& x : out.c) mul(x, x, f);
  return out;
}

// The sign of p just after the point r: of p there, or of its first derivative not zero there
// (Taylor); 0 only for p = 0.
int sign_just_after(const Poly& p, Root& r) {
  for (Poly g = p; !g.is_zero(); g = algebra::derivative(g))
    if (const int s = algebra::sign_at(g, r)) return s;
  return 0;
}

bool holds(const Condition& c, int sign) {
  return sign > 0 || (sign == 0 && !c.strict);
}

// The condition's verdict for all of [0, 1] (which holds any window) when the polynomial's sign
// is constant there: +1 holds throughout, -1 fails throughout, 0 not known.
int throughout(const Condition& c) {
  if (c.p.is_zero()) return c.strict ? -1 : 1;
  if (c.p.degree() > 0 && !algebra::no_root_in_unit(c.p)) return 0;
  return holds(c, c.p.c[0].sign()) ? 1 : -1;
}

class SeparationSearch {
 public:
  SeparationSearch(const Query& q, double t0, double t1, bool want_time);
  std::vector<Root>& found() { return found_; }
  const Dyadic& t1() const { return t1_; }

 private:
  void vertex_face(const PVec& p, const PVec& a, const PVec& b, const PVec& c);
  void edge_edge(const PVec& a0, const PVec& a1, const PVec& b0, const PVec& b1);
  void point_point(const PVec& p, const PVec& a);
  void point_edge(const PVec& p, const PVec& a, const PVec& b);
  void face(const PVec& p, const PVec& a, const PVec& b, const PVec& c);
  void interior(const PVec& a0, const PVec& a1, const PVec& b0, const PVec& b1);
  bool boxes_apart(const std::array<PVec, 4>& v, bool vertex_face) const;
  // δ^2 q - p >= 0: p <= δ^2 q, scaled by a positive power of two where δ^2 is not an integer.
  Condition within(const Poly& p, const Poly& q) const;
  void decide(Piece piece);
  bool qualifies(const Piece& piece, Root& r);
  bool done() const { return (!want_time_ && !found_.empty()) || at_start_; }

  Dyadic t0_, t1_;
  bool want_time_;
  SquaredDistance d2_;
  bool at_start_ = false;
  std::deque<Poly> keep_;  // the squarefree polynomials the roots point into (stable addresses)
  std::vector<Root> found_;
};

SeparationSearch::SeparationSearch(const Query& q, double t0, double t1, bool want_time)
    : t0_(Dyadic::of(t0)), t1_(Dyadic::of(t1)), want_time_(want_time) {
  if (!(0 <= t0 && t0 <= t1 && t1 <= 1))
    throw std::invalid_argument("ccd: the time window must satisfy 0 <= t0 <= t1 <= 1");
  const double delta = q.min_distance;
  if (!(std::isfinite(delta) && delta > 0))
    throw std::invalid_argument("ccd: the minimum distance must be finite and >= 0");
  long k = 0;
  const std::array<PVec, 4> v = integer_paths(q, &k);
  const algebra::Binary b = algebra::Binary::of(delta);  // δ 2^k = m 2^(e + k)
  d2_.m = Int(b.m) * Int(b.m);
  d2_.e = 2 * (long(b.e) + k);
  const bool vf = q.kind == QueryKind::VertexFace;
  if (boxes_apart(v, vf)) return;
  if (vf)
    vertex_face(v[0], v[1], v[2], v[3]);
  else
    edge_edge(v[0], v[1], v[2], v[3]);
}

Condition SeparationSearch::within(const Poly& p, const Poly& q) const {
  if (d2_.e >= 0) return {times(q, d2_.m << (unsigned long)d2_.e) - p};
  return {times(q, d2_.m) - times(p, Int(1) << (unsigned long)(-d2_.e))};
}

// The cheap exact early-out: the primitives stay inside the boxes of their corners at t = 0 and
// t = 1 over the whole step (linear motion, convex sets), so boxes farther apart than δ decide.
bool SeparationSearch::boxes_apart(const std::array<PVec, 4>& v, bool vertex_face) const {
  const int split = vertex_face ? 1 : 2;  // the first primitive's corners are v[0, split)
  Int gaps;                               // the squared distance of the boxes
  for (int axis = 0; axis < 3; ++axis) {
    Int lo[2], hi[2];
    bool seen[2] = {false, false};
    for (int i = 0; i < 4; ++i) {
      const Poly& p = axis == 0 ? v[i].x : axis == 1 ? v[i].y : v[i].z;
      const Int at0 = p.is_zero() ? Int(0) : p.c[0];
      const Int at1 = p.degree() == 1 ? at0 + p.c[1] : at0;
      const int side = i < split ? 0 : 1;
      for (const Int* x : {&at0, &at1}) {
        if (!seen[side] || *x < lo[side]) lo[side] = *x;
        if (!seen[side] || *x > hi[side]) hi[side] = *x;
        seen[side] = true;
      }
    }
    const Int gap = lo[1] > hi[0] ? lo[1] - hi[0] : lo[0] > hi[1] ? lo[0] - hi[1] : Int(0);
    addmul(gaps, gap, gap);
  }
  return throughout(within(constant(gaps), constant(1))) < 0;
}

// The pieces, cheapest first: the verdict mostly ends at the first that holds somewhere.
void SeparationSearch::vertex_face(const PVec& p, const PVec& a, const PVec& b, const PVec& c) {
  for (const PVec* x : {&a, &b, &c})
    if (!done()) point_point(p, *x);
  for (const auto& e : {std::array<const PVec*, 2>{&a, &b}, {&b, &c}, {&c, &a}})
    if (!done()) point_edge(p, *e[0], *e[1]);
  if (!done()) face(p, a, b, c);
}

void SeparationSearch::edge_edge(const PVec& a0, const PVec& a1, const PVec& b0, const PVec& b1) {
  for (const auto& e : {std::array<const PVec*, 2>{&a0, &b0}, {&a0, &b1}, {&a1, &b0}, {&a1, &b1}})
    if (!done()) point_point(*e[0], *e[1]);
  for (const auto& e : {std::array<const PVec*, 3>{&a0, &b0, &b1},
                        {&a1, &b0, &b1},
                        {&b0, &a0, &a1},
                        {&b1, &a0, &a1}})
    if (!done()) point_edge(*e[0], *e[1], *e[2]);
  if (!done()) interior(a0, a1, b0, b1);
}

void SeparationSearch::point_point(const PVec& p, const PVec& a) {
  const PVec d = p - a;
  decide({within(dot(d, d), constant(1))});
}

// The foot of p on the line of [a, b] inside the closed segment, the distance to the line at
// most δ: |e x w|^2 = |e|^2 |w|^2 - (e.w)^2 <= δ^2 |e|^2. The ends are point_point pieces.
void SeparationSearch::point_edge(const PVec& p, const PVec& a, const PVec& b) {
  const PVec e = b - a, w = p - a, ew = cross(e, w);
  const Poly ee = dot(e, e), along = dot(e, w);
  decide({{ee, true}, {along}, {ee - along}, within(dot(ew, ew), ee)});
}

// The projection of p inside the triangle (|n|^2 times its barycentric coordinates >= 0), the
// distance to the plane at most δ: ((p - a).n)^2 <= δ^2 |n|^2.
void SeparationSearch::face(const PVec& p, const PVec& a, const PVec& b, const PVec& c) {
  const PVec ab = b - a, n = cross(ab, c - a);
  const Poly nn = dot(n, n), h = dot(p - a, n);
  decide({{nn, true},
          {dot(n, cross(ab, p - a))},
          {dot(n, cross(c - b, p - b))},
          {dot(n, cross(a - c, p - c))},
          within(h * h, nn)});
}

// The closest points of the two lines (n = d1 x d2 != 0): a0 + (s / |n|^2) d1 and
// b0 + (u / |n|^2) d2 with s = (r x d2).n, u = (r x d1).n, r = b0 - a0, both inside their
// segments; their distance |r.n| / |n| at most δ.
void SeparationSearch::interior(const PVec& a0, const PVec& a1, const PVec& b0, const PVec& b1) {
  const PVec d1 = a1 - a0, d2 = b1 - b0, r = b0 - a0, n = cross(d1, d2);
  const Poly nn = dot(n, n), s = dot(cross(r, d2), n), u = dot(cross(r, d1), n), h = dot(r, n);
  decide({{nn, true}, {s}, {nn - s}, {u}, {nn - u}, within(h * h, nn)});
}

// Records the piece's infimum in [t0, t1] if it is not empty: the first candidate (t0, then the
// roots of each polynomial in turn, increasing) where it qualifies. Conditions of one sign
// throughout [0, 1] are decided first, without roots.
void SeparationSearch::decide(Piece piece) {
  Piece open;
  for (Condition& c : piece) {
    const int verdict = throughout(c);
    if (verdict < 0) return;
    if (verdict == 0) open.push_back(std::move(c));
  }
  Root start = Root::at(t0_);
  if (open.empty() || qualifies(open, start)) {
    found_.push_back(start);
    at_start_ = true;
    return;
  }
  for (const Condition& c : open) {
    keep_.push_back(c.p);  // roots_in makes it squarefree
    for (Root& r : algebra::roots_in(keep_.back(), t0_, t1_))
      if (qualifies(open, r)) {
        found_.push_back(r);
        break;
      }
    if (!want_time_ && !found_.empty()) return;
  }
}

// The piece holds at r, or on an interval just after r inside the window.
bool SeparationSearch::qualifies(const Piece& piece, Root& r) {
  bool at = true;
  for (const Condition& c : piece)
    if (!(at = holds(c, algebra::sign_at(c.p, r)))) break;
  if (at) return true;
  if (r.exact() && algebra::compare(r.lo(), t1_) == 0) return false;  // nothing after t1
  for (const Condition& c : piece)
    if (!holds(c, sign_just_after(c.p, r))) return false;
  return true;
}

}  // namespace

CcdContact separation_ccd(const Query& q, const CcdOptions& options) {
  SeparationSearch s(q, options.t0, options.t1, true);
  return earliest_contact(s.found(), unsigned(std::max(options.time_bits, 0)), true);
}

bool separation_hit(const Query& q) {
  SeparationSearch s(q, 0, 1, false);
  return !s.found().empty();
}

Toi separation_toi(const Query& q, double t0, double t1, double width) {
  SeparationSearch s(q, t0, t1, true);
  return earliest_toi(s.found(), width);
}

int separation_compare_with_toi(const Query& q, double t) {
  if (!(t >= 0 && t <= 1)) return t < 0 ? -1 : 1;  // outside the step (NaN counts as late)
  // t*_δ <= t exactly when [0, t] holds a candidate; then t*_δ = t when all of them are t.
  SeparationSearch before(q, 0, t, true);
  if (!before.found().empty()) return window_end_against_earliest(before.found(), before.t1());
  if (SeparationSearch(q, t, 1, false).found().empty())
    throw std::invalid_argument("compare_with_toi: the query does not come within its distance");
  return -1;
}

}  // namespace fdh::exact
