#include "fdh/exact/ccd.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "earliest_contact.hpp"
#include "moving_points.hpp"
#include "polynomial.hpp"
#include "separation.hpp"

namespace fdh::exact {
namespace {

using algebra::Poly;
using algebra::Root;
using algebra::sign_at;

// A point or vector at one dyadic time t = a / 2^k with its coordinates scaled by 2^k (each
// coordinate of a moving point is linear: c0 2^k + c1 a). The contact conditions are
// homogeneous in the coordinates, so their signs at an exact time need no polynomial.
struct IVec {
  algebra::Int x, y, z;
};
algebra::Int at(const Poly& p, const algebra::Dyadic& t) {  // p of degree <= 1, times 2^k
  algebra::Int v;
  if (!p.is_zero()) mul_2exp(v, p.c[0], t.k);
  if (p.degree() == 1) addmul(v, p.c[1], t.a);
  return v;
}
IVec at(const PVec& v, const algebra::Dyadic& t) {
  return {at(v.x, t), at(v.y, t), at(v.z, t)};
}
IVec operator-(const IVec& a, const IVec& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
IVec cross(const IVec& a, const IVec& b) {
  IVec r;
  mul(r.x, a.y, b.z), submul(r.x, a.z, b.y);
  mul(r.y, a.z, b.x), submul(r.y, a.x, b.z);
  mul(r.z, a.x, b.y), submul(r.z, a.y, b.x);
  return r;
}
algebra::Int dot(const IVec& a, const IVec& b) {
  algebra::Int r;
  mul(r, a.x, b.x), addmul(r, a.y, b.y), addmul(r, a.z, b.z);
  return r;
}

// The contact conditions, once for both forms: V = PVec with sign(g) the sign of the polynomial
// g at a root, or V = IVec with sign(x) the sign of the integer x at an exact time. Each
// condition is built only when asked: most roots are decided by the first one or two.
template <class V, class Sign>
bool is_zero_at(const V& v, Sign sign) {
  return sign(v.x) == 0 && sign(v.y) == 0 && sign(v.z) == 0;
}

// Closed segment membership, degenerate segments included: p is on [a, b] iff p - a is
// parallel to b - a, w = (p - a) x (b - a) = 0, and h = (p - a).(p - b) <= 0. With a = b, w
// vanishes and h is |p - a|^2, so only p = a passes.
template <class V, class Sign>
bool on_segment(const V& p, const V& a, const V& b, Sign sign) {
  const V pa = p - a;
  return is_zero_at(cross(pa, b - a), sign) && sign(dot(pa, p - b)) <= 0;
}

// p in the closed triangle abc, given coplanarity; bc = (b - p) x (c - p), shared with f.
template <class V, class Sign>
bool inside(const V& p, const V& a, const V& b, const V& c, const V& bc, Sign sign) {
  const V n = cross(b - a, c - a);
  if (is_zero_at(n, sign))  // a zero-area triangle is the union of its edges
    return on_segment(p, a, b, sign) || on_segment(p, b, c, sign) || on_segment(p, c, a, sign);
  // |n|^2 times p's barycentric coordinates.
  if (sign(dot(n, bc)) < 0) return false;
  const V ap = a - p;
  return sign(dot(n, cross(c - p, ap))) >= 0 && sign(dot(n, cross(ap, b - p))) >= 0;
}

// The closed segments [a0, a1] and [b0, b1] meet, given coplanarity; web = (b0 - a0) x
// (b1 - b0), shared with f.
template <class V, class Sign>
bool meet(const V& a0, const V& a1, const V& b0, const V& b1, const V& web, Sign sign) {
  const V ea = a1 - a0, m = cross(ea, b1 - b0);
  if (is_zero_at(m, sign))  // parallel or zero-length: an end of one lies on the other
    return on_segment(a0, b0, b1, sign) || on_segment(a1, b0, b1, sign) ||
           on_segment(b0, a0, a1, sign) || on_segment(b1, a0, a1, sign);
  // With m != 0: a0 + (s/mm) ea = b0 + (u/mm) eb.
  const auto s = dot(web, m), u = dot(cross(b0 - a0, ea), m);
  if (sign(s) < 0 || sign(u) < 0) return false;
  const auto mm = dot(m, m);
  return sign(mm - s) >= 0 && sign(mm - u) >= 0;
}

// The signs that the conditions take: of a polynomial at a root, or of an integer.
struct SignAt {
  Root& r;
  int operator()(const Poly& g) const { return sign_at(g, r); }
};
int integer_sign(const algebra::Int& x) {
  return x.sign();
}

class Search {
 public:
  Search(const CcdOptions& o, bool want_time)
      : t0_(algebra::Dyadic::of(o.t0)), t1_(algebra::Dyadic::of(o.t1)), want_time_(want_time) {}

  void vertex_face(const PVec& p, const PVec& a, const PVec& b, const PVec& c);
  void edge_edge(const PVec& a0, const PVec& a1, const PVec& b0, const PVec& b1);

  // The earliest contact found (earliest_contact.hpp).
  CcdContact result(unsigned long bits) { return earliest_contact(found_, bits, want_time_); }
  Toi toi(double width) { return earliest_toi(found_, width); }
  int end_against_contact() const { return window_end_against_earliest(found_, t1_); }

 private:
  // Records the first of `roots` (increasing) where `ok` holds.
  template <class Ok>
  bool first_where(algebra::Roots roots, Ok ok) {
    for (Root& r : roots)
      if (ok(r)) {
        found_.push_back(r);
        return true;
      }
    return false;
  }
  // Records the earliest root in [t0, t1] common to `zeros` (not all zero) where `ok` holds.
  template <class Ok>
  bool first_common_root(std::initializer_list<const Poly*> zeros, Ok ok) {
    return first_where(common_roots(zeros), ok);
  }
  // The skeleton of both kinds, given the coplanarity polynomial f, its roots in the window
  // (when f != 0), the contact condition at a coplanar time, and the (vertex, edge start, edge
  // end) triples that a first contact of a coplanar-throughout motion must pass through.
  template <class Touch>
  void first_contact(const Poly& f, algebra::Roots times, Touch touch,
                     std::initializer_list<std::array<const PVec*, 3>> vertex_edge) {
    if (!f.is_zero()) {
      first_where(std::move(times), touch);
      return;
    }
    Root start = Root::at(t0_);
    if (touch(start)) found_at_start();
    for (const auto& e : vertex_edge)
      if (!done()) point_edge(*e[0], *e[1], *e[2]);
  }
  // The roots in [t0, t1] common to `zeros` (not all zero), increasing.
  algebra::Roots common_roots(std::initializer_list<const Poly*> zeros) {
    // One of them without roots in [0, 1], which holds the window: the common case, decided
    // cheaply (roots_in's own Bernstein test decides it for one polynomial).
    if (zeros.size() > 1)
      for (const Poly* z : zeros)
        if (algebra::no_root_in_unit(*z)) return {};
    // The gcd from the lowest degree up, zeros skipped (gcd(g, 0) = g): the fewest remainders.
    std::array<const Poly*, 3> order{};
    std::size_t n = 0;
    for (const Poly* z : zeros)  // insertion by degree
      if (!z->is_zero()) {
        std::size_t i = n++;
        for (; i > 0 && order[i - 1]->degree() > z->degree(); --i) order[i] = order[i - 1];
        order[i] = z;
      }
    if (n == 0) return {};
    Poly g = *order[0];
    for (std::size_t i = 1; i < n; ++i) {
      if (g.degree() == 0) return {};  // a nonzero constant divides everything after it
      g = algebra::gcd(g, *order[i]);
    }
    if (g.degree() < 1) return {};
    keep_.push_back(std::move(g));
    return algebra::roots_in(keep_.back(), t0_, t1_);
  }
  bool found_at_start() {
    found_.push_back(Root::at(t0_));
    at_start_ = true;
    return true;
  }
  // Any contact answers the verdict; one at the window's start is the earliest possible.
  bool done() const { return (!want_time_ && !found_.empty()) || at_start_; }

  bool point_point(const PVec& p, const PVec& a);
  bool point_edge(const PVec& p, const PVec& a, const PVec& b);

  algebra::Dyadic t0_, t1_;
  bool want_time_;
  bool at_start_ = false;  // a contact found at t0
  // The squarefree polynomials that the roots point into: one for f, else at most two per
  // vertex-edge pair (point_edge), four pairs for edge-edge.
  algebra::InlineVector<Poly, 8> keep_;
  // Candidates for the earliest contact: at most one per first_where or found_at_start call.
  algebra::InlineVector<Root, 10> found_;
};

bool Search::point_point(const PVec& p, const PVec& a) {
  const PVec d = p - a;
  if (d.is_zero()) return found_at_start();
  return first_common_root({&d.x, &d.y, &d.z}, [](Root&) { return true; });
}

// Point on a moving segment. If p, a, b are not collinear throughout, contacts are common roots
// of the cross product. If they are, the first contact is at the start or where p meets an end.
bool Search::point_edge(const PVec& p, const PVec& a, const PVec& b) {
  // As on_segment, over the step.
  const PVec w = cross(p - a, b - a);
  const auto h_at_most_0 = [&](Root& r) {  // (p - a).(p - b) <= 0
    if (!r.exact()) return sign_at(dot(p - a, p - b), r) <= 0;
    const IVec pt = at(p, r.lo());
    return dot(pt - at(a, r.lo()), pt - at(b, r.lo())).sign() <= 0;
  };
  if (!w.is_zero()) return first_common_root({&w.x, &w.y, &w.z}, h_at_most_0);
  Root start = Root::at(t0_);
  if (h_at_most_0(start)) return found_at_start();
  const bool hit_a = point_point(p, a);
  if (done()) return true;
  return point_point(p, b) || hit_a;
}

void Search::vertex_face(const PVec& p, const PVec& a, const PVec& b, const PVec& c) {
  const PVec bc = cross(b - p, c - p);
  const Poly f = dot(a - p, bc);  // 6 x signed volume: 0 iff coplanar
  algebra::Roots times = f.is_zero() ? algebra::Roots{} : common_roots({&f});
  if (!f.is_zero() && times.empty()) return;  // never coplanar: the common case, decided here
  const auto touch = [&](Root& r) {
    if (!r.exact()) return inside(p, a, b, c, bc, SignAt{r});
    const algebra::Dyadic t = r.lo();  // an exact time: on integers, no polynomial
    const IVec pt = at(p, t), bt = at(b, t), ct = at(c, t);
    return inside(pt, at(a, t), bt, ct, cross(bt - pt, ct - pt), integer_sign);
  };
  // Coplanar throughout: a first contact after the start puts p on an edge, since inside a
  // non-degenerate triangle it would have been inside a moment earlier.
  first_contact(f, std::move(times), touch, {{&p, &a, &b}, {&p, &b, &c}, {&p, &c, &a}});
}

void Search::edge_edge(const PVec& a0, const PVec& a1, const PVec& b0, const PVec& b1) {
  const PVec web = cross(b0 - a0, b1 - b0);
  const Poly f = dot(a1 - a0, web);  // 0 iff coplanar
  algebra::Roots times = f.is_zero() ? algebra::Roots{} : common_roots({&f});
  if (!f.is_zero() && times.empty()) return;
  const auto touch = [&](Root& r) {
    if (!r.exact()) return meet(a0, a1, b0, b1, web, SignAt{r});
    const algebra::Dyadic t = r.lo();  // an exact time: on integers, no polynomial
    const IVec at0 = at(a0, t), bt0 = at(b0, t), bt1 = at(b1, t);
    return meet(at0, at(a1, t), bt0, bt1, cross(bt0 - at0, bt1 - bt0), integer_sign);
  };
  // Coplanar throughout: segments that cross properly crossed a moment earlier too, so a first
  // contact after the start puts an end of one on the other.
  first_contact(f, std::move(times), touch,
                {{&a0, &b0, &b1}, {&a1, &b0, &b1}, {&b0, &a0, &a1}, {&b1, &a0, &a1}});
}

// Searches [o.t0, o.t1] for every candidate of the earliest contact.
void search(const Query& q, const CcdOptions& o, Search& search) {
  if (!(0 <= o.t0 && o.t0 <= o.t1 && o.t1 <= 1))
    throw std::invalid_argument("ccd: the time window must satisfy 0 <= t0 <= t1 <= 1");
  const std::array<PVec, 4> v = integer_paths(q);
  if (q.kind == QueryKind::VertexFace)
    search.vertex_face(v[0], v[1], v[2], v[3]);
  else
    search.edge_edge(v[0], v[1], v[2], v[3]);
}

CcdContact run(const Query& q, const CcdOptions& o, bool want_time) {
  Search s(o, want_time);
  search(q, o, s);
  return s.result(unsigned(std::max(o.time_bits, 0)));
}

}  // namespace

// A minimum separation δ != 0 goes to its own search (separation.hpp); δ = 0 is contact.
CcdContact ccd(const Query& q, const CcdOptions& options) {
  if (q.min_distance != 0) return separation_ccd(q, options);
  return run(q, options, true);
}

bool ccd_hit(const Query& q) {
  if (q.min_distance != 0) return separation_hit(q);
  return run(q, CcdOptions{}, false).hit;
}

Toi ccd_toi(const Query& q, double t0, double t1, double width) {
  if (!(width >= kMinToiWidth && width <= 1))
    throw std::invalid_argument("ccd_toi: the width must lie in [2^-52, 1]");
  if (q.min_distance != 0) return separation_toi(q, t0, t1, width);
  const CcdOptions o{t0, t1, 0};
  Search s(o, true);
  search(q, o, s);
  // Refined until the doubles are `width` apart: an end that is not a double rounds outward by
  // up to one of its ulps, so a time such as 1/3 needs its two neighbouring doubles; an exact
  // time that is a double (a bisection point may land on it) needs none.
  return s.toi(width);
}

int compare_with_toi(const Query& q, double t) {
  if (q.min_distance != 0) return separation_compare_with_toi(q, t);
  if (!(t >= 0 && t <= 1)) return t < 0 ? -1 : 1;  // outside the step (NaN counts as late)
  // A contact in [0, t] exactly when t* <= t; then t* = t exactly when every candidate for the
  // earliest contact in [0, t] is t itself (Search::end_against_contact).
  const CcdOptions before{0, t, 0};
  Search s(before, true);
  search(q, before, s);
  if (s.result(0).hit) return s.end_against_contact();
  if (!run(q, CcdOptions{t, 1, 0}, false).hit)
    throw std::invalid_argument("compare_with_toi: the query has no contact");
  return -1;
}

}  // namespace fdh::exact
