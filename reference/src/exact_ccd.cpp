#include "fdh/exact/ccd.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "polynomial.hpp"

namespace fdh::exact {
namespace {

using algebra::Poly;
using algebra::Root;
using algebra::sign_at;

// A point or vector whose coordinates are polynomials in t.
struct PVec {
  Poly x, y, z;
  bool is_zero() const { return x.is_zero() && y.is_zero() && z.is_zero(); }
};
PVec operator-(const PVec& a, const PVec& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
PVec cross(const PVec& a, const PVec& b) {
  using algebra::sum_of_products;
  return {sum_of_products({{a.y, b.z}, {a.z, b.y, true}}),
          sum_of_products({{a.z, b.x}, {a.x, b.z, true}}),
          sum_of_products({{a.x, b.y}, {a.y, b.x, true}})};
}
Poly dot(const PVec& a, const PVec& b) {
  return algebra::sum_of_products({{a.x, b.x}, {a.y, b.y}, {a.z, b.z}});
}

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

// The four moving points with their coordinates scaled by one power of two into integers:
// every condition below is homogeneous in the coordinates, so no sign changes.
std::array<PVec, 4> integer_paths(const Query& q) {
  algebra::Binary d[24];  // x = m 2^e; scaled by 2^k, each is the integer m 2^(e + k)
  long k = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 3; ++j) {
      algebra::Binary& e = d[3 * i + j];
      e = algebra::Binary::of(j == 0 ? q.x[i].x : j == 1 ? q.x[i].y : q.x[i].z);
      if (e.m != 0) k = std::max(k, -long(e.e));
    }
  algebra::Int c[24];
  for (int i = 0; i < 24; ++i)
    if (d[i].m != 0) mul_2exp(c[i], algebra::Int(d[i].m), (unsigned long)(d[i].e + k));
  std::array<PVec, 4> v;
  for (int i = 0; i < 4; ++i) {
    v[i].x = Poly::linear(c[3 * i], c[3 * i + 12]);
    v[i].y = Poly::linear(c[3 * i + 1], c[3 * i + 13]);
    v[i].z = Poly::linear(c[3 * i + 2], c[3 * i + 14]);
  }
  return v;
}

class Search {
 public:
  Search(const CcdOptions& o, bool want_time)
      : t0_(algebra::Dyadic::of(o.t0)), t1_(algebra::Dyadic::of(o.t1)), want_time_(want_time) {}

  void vertex_face(const PVec& p, const PVec& a, const PVec& b, const PVec& c);
  void edge_edge(const PVec& a0, const PVec& a1, const PVec& b0, const PVec& b1);

  // The earliest contact found, refined to width < 2^-bits (bits = 0: as found). May be called
  // again with more bits: the candidates' intervals are refined in place.
  CcdContact result(unsigned long bits);

  // The earliest contact found as doubles, outward, refined until they are at most `width`
  // apart and t_lo > 0 unless t* = 0 (see ccd_toi). No strings, no rationals: dyadics only.
  Toi toi(double width);

  // Where the window's end t1 lies against the earliest contact t* found in [t0, t1] (there must
  // be one): 0 if t* = t1, +1 if t* < t1. A candidate is exact at t1 or lies in an open interval
  // (lo, hi) with hi <= t1 (polynomial.hpp's Root), so no refinement is needed.
  int end_against_contact() const {
    for (const Root& r : found_)
      if (!r.exact() || r.lo().value() != t1_.value()) return 1;
    return 0;
  }

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

// Bounds as doubles, outward: get_d truncates, which rounds down for q >= 0.
double up(const mpq_class& q) {
  const double d = q.get_d();
  return mpq_class(d) < q ? std::nextafter(d, 2.0) : d;
}

// The bits that make an exact interval narrower than `width`, with two more for the outward
// rounding to doubles (each end moves by less than 2^-53 in [0, 1]).
unsigned long bits_for(double width) {
  return unsigned(std::max(0, -std::ilogb(width))) + 2;
}

// A dyadic rounded to a double downward or upward: to nearest by its leading bits, then one
// step where that went the wrong way.
double rounded(const algebra::Dyadic& x, bool upward) {
  long e = 0;
  const double m = x.a.frexp(&e);
  double d = std::ldexp(m, int(e - long(x.k)));
  const int c = algebra::compare(algebra::Dyadic::of(d), x);
  if (upward ? c < 0 : c > 0) d = std::nextafter(d, upward ? 2.0 : -1.0);
  return d;
}

Toi Search::toi(double width) {
  if (found_.empty()) return Toi{};
  // Each candidate's interval holds its time; the earliest lies in [min lo, min hi].
  for (unsigned long bits = bits_for(width);; bits += 8) {
    const algebra::Dyadic* lo = nullptr;
    const algebra::Dyadic* hi = nullptr;
    algebra::Dyadic los[10], his[10];
    for (std::size_t i = 0; i < found_.size(); ++i) {
      Root& r = found_[i];
      algebra::narrow_to_doubles(r);  // mostly narrow enough at once
      algebra::refine(r, bits);
      los[i] = r.lo(), his[i] = r.hi();
      if (!lo || algebra::compare(los[i], *lo) < 0) lo = &los[i];
      if (!hi || algebra::compare(his[i], *hi) < 0) hi = &his[i];
    }
    const Toi t{true, rounded(*lo, false), rounded(*hi, true)};
    // t_lo > 0 unless t* = 0: a contact just after 0 needs as many bits as it is close to 0
    // (one below 2^-1074, the smallest double, keeps t_lo = 0: no double lies below it).
    if (t.t_hi - t.t_lo <= width && (t.t_lo > 0 || t.t_hi == 0 || bits > 1100)) return t;
    if (bits > 1100)  // the interval holds two doubles apart by > 2^-52 only if wider than that
      throw std::logic_error("ccd_toi: the contact time did not narrow");
  }
}

CcdContact Search::result(unsigned long bits) {
  CcdContact out;
  if (found_.empty()) return out;
  out.hit = true;
  if (!want_time_) return out;
  // Each candidate's interval holds its time; the earliest lies in [min lo, min hi].
  mpq_class lo = 2, hi = 2;
  for (Root& r : found_) {
    if (bits > 0) algebra::refine(r, bits);
    const mpq_class rl = r.lo().value(), rh = r.hi().value();
    if (rl < lo) lo = rl;
    if (rh < hi) hi = rh;
  }
  out.time_lo = lo.get_str();
  out.time_hi = hi.get_str();
  out.time_lo_down = lo.get_d();
  out.time_hi_up = up(hi);
  return out;
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

CcdContact ccd(const Query& q, const CcdOptions& options) {
  return run(q, options, true);
}

bool ccd_hit(const Query& q) {
  return run(q, CcdOptions{}, false).hit;
}

Toi ccd_toi(const Query& q, double t0, double t1, double width) {
  if (!(width >= kMinToiWidth && width <= 1))
    throw std::invalid_argument("ccd_toi: the width must lie in [2^-52, 1]");
  const CcdOptions o{t0, t1, 0};
  Search s(o, true);
  search(q, o, s);
  // Refined until the doubles are `width` apart: an end that is not a double rounds outward by
  // up to one of its ulps, so a time such as 1/3 needs its two neighbouring doubles; an exact
  // time that is a double (a bisection point may land on it) needs none.
  return s.toi(width);
}

int compare_with_toi(const Query& q, double t) {
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
