#include "fdh/ccd/robust.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "ccd_robust_conditions.hpp"
#include "ccd_robust_delta.hpp"
#include "ccd_robust_integer.hpp"
#include "fdh/interval.hpp"
#include "fdh/orient3d_exact.hpp"
#include "fdh/orient3d_filter.hpp"
#include "motion.hpp"

namespace fdh {
namespace {

// ---- Stage 1: the Bernstein coefficients of the coplanarity cubic, with static bounds.

double det(const Vec3& u, const Vec3& v, const Vec3& w) {
  return u.z * (v.x * w.y - w.x * v.y) + v.z * (w.x * u.y - u.x * w.y) +
         w.z * (u.x * v.y - v.x * u.y);
}

// f(t) = det(U(t), V(t), W(t)) with U(t) = (1 - t) U0 + t U1 and so on. By multilinearity its
// Bernstein coefficients on [0, 1] are det(U0,V0,W0), the means of the three determinants with
// one vector at t = 1, of those with two, and det(U1,V1,W1). f lies in their convex hull.
// Each vector is one rounded difference, so each determinant is off by at most
// kOrient3dErrBound P with P = Mx My Mz the product of the largest |coordinates| over all six
// vectors, and a mean of three by kOrient3dMeanOfThreeErrBound P (orient3d_filter.hpp).
struct Bernstein {
  double b[4];
  double err;   // |computed - exact| for every coefficient
  double bmax;  // >= |every exact coefficient|, so >= |f| on [0, 1]
  bool valid;   // false outside the filter's range: nothing is certain
};

Bernstein bernstein(const Vec3 u[2], const Vec3 v[2], const Vec3 w[2]) {
  double mx = 0, my = 0, mz = 0;
  for (const Vec3* s : {u, v, w})
    for (int i = 0; i < 2; ++i) {
      const double ax = std::fabs(s[i].x), ay = std::fabs(s[i].y), az = std::fabs(s[i].z);
      mx = ax > mx ? ax : mx, my = ay > my ? ay : my, mz = az > mz ? az : mz;
    }
  Bernstein r{};
  r.valid = in_filter_range(mx) && in_filter_range(my) && in_filter_range(mz);
  if (!r.valid) return r;
  const double p = mx * my * mz;
  r.b[0] = det(u[0], v[0], w[0]);
  r.b[1] = (det(u[1], v[0], w[0]) + det(u[0], v[1], w[0]) + det(u[0], v[0], w[1])) / 3;
  r.b[2] = (det(u[1], v[1], w[0]) + det(u[1], v[0], w[1]) + det(u[0], v[1], w[1])) / 3;
  r.b[3] = det(u[1], v[1], w[1]);
  // b[0] and b[3] are off by kOrient3dErrBound P, b[1] and b[2] (means of three) by
  // kOrient3dMeanOfThreeErrBound P, the larger: one bound for all four (orient3d_filter.hpp).
  r.err = kOrient3dMeanOfThreeErrBound * p;
  r.bmax = 6 * p + r.err;
  return r;
}

int bernstein_sign(const Bernstein& f) {
  if (!f.valid) return 0;
  int sign = 0;
  for (int i = 0; i < 4; ++i) {
    const int s = sign_beyond(f.b[i], f.err);
    if (s == 0 || (sign != 0 && s != sign)) return 0;
    sign = s;
  }
  return sign;
}

// ---- Stage 2: the inside conditions by intervals, and root isolation by subdivision of f.

using namespace motion;
using namespace ccd_conditions;

// What the conditions look like at one instant, estimated in plain floating point, relative to
// the largest in size. Never a verdict: it only tells the filter where intervals would fail,
// so that it gives up (or moves on) without paying for them.
struct Look {
  double lowest = 0;     // min g_i / size: clearly < 0 where well below the intervals' width
  double near_zero = 0;  // min |g_i| / size: about 0 where below it
  bool hopeless(double width) const { return near_zero <= width && lowest >= -width; }
};
// The largest |g_i|.
double size_of(const Conditions<double>& c) {
  double size = 0;
  for (int i = 0; i < c.n; ++i) size = std::max(size, std::fabs(c.g[i]));
  return size;
}

Look look_at(const Query& q, double t) {
  const Conditions<double> c = conditions_at(q, t);
  const double size = size_of(c);
  if (!(size > 0)) return {0, 0};  // all 0 (parallel edges, a point triangle): hopeless
  Look look{1, 1};
  for (int i = 0; i < c.n; ++i) {
    look.lowest = std::min(look.lowest, c.g[i] / size);
    look.near_zero = std::min(look.near_zero, std::fabs(c.g[i]) / size);
  }
  return look;
}

// f on a piece of [0, 1], as its Bernstein coefficients there, found by de Casteljau
// subdivision from stage 1's. The piece's true ends are dyadic but may need more bits than a
// double has; lo and hi are them rounded, within `slack` (the sum of the roundings).
struct Piece {
  double lo, hi, slack;
  double b[4];
  int depth;
};

// Splits p at lo + s (hi - lo) by de Casteljau. Each new coefficient is a convex combination of
// the old, so the error of the exact ones carries over unchanged, plus the roundings of three
// levels of (1 - s) x + s y: at most 9 eps times the largest |coefficient| per split; bound()
// allows 16. s and 1 - s must both be exact: 7/16 and 9/16, or see exact_complement().
void split(const Piece& p, double s, Piece& left, Piece& right) {
  const double r = 1 - s;
  const double a0 = r * p.b[0] + s * p.b[1], a1 = r * p.b[1] + s * p.b[2],
               a2 = r * p.b[2] + s * p.b[3];
  const double c0 = r * a0 + s * a1, c1 = r * a1 + s * a2;
  const double m = r * c0 + s * c1;
  const double t = p.lo + s * (p.hi - p.lo);
  const double slack = p.slack + 0x1p-51;  // t's two roundings, in [0, 1]: < 2^-52
  left = {p.lo, t, slack, {p.b[0], a0, c0, m}, p.depth + 1};
  right = {t, p.hi, slack, {m, c1, a2, p.b[3]}, p.depth + 1};
}

// The error of a piece's coefficients at its depth (the + 2^-1070 covers underflow).
double bound(const Bernstein& f, int depth) {
  return f.err + depth * (16 * kEps * f.bmax + 0x1p-1070);
}

// Sign variations of the certain signs; -1 if some sign is uncertain.
int variations(const Piece& p, double err) {
  int prev = 0, v = 0;
  for (const double c : p.b) {
    const int s = sign_beyond(c, err);
    if (s == 0) return -1;
    if (prev != 0 && s != prev) ++v;
    prev = s;
  }
  return v;
}

// True if no coefficient of the piece has a certain sign.
bool flat(const Piece& p, double err) {
  for (const double c : p.b)
    if (sign_beyond(c, err) != 0) return false;
  return true;
}

// The conditions g_i over a piece: its rounded ends pushed out by twice its slack.
Conditions<Interval> conditions(const Query& q, const Piece& p) {
  return conditions_at(q, Interval{p.lo - 2 * p.slack, p.hi + 2 * p.slack});
}

// Interval evaluations of the conditions allowed per query. One costs some ten times the whole
// first stage, and a query that needs more (f zero or nearly so for a long time: coplanar
// motion) almost never gets decided by them: it goes to the exact test sooner.
constexpr int kMaxEvaluations = 4;

// Keeps the half of `p` that holds f's root (certain opposite signs at its ends): split at the
// middle, or at 7/16 when the root sits (nearly) on the middle, since handcrafted contacts sit
// at dyadic times. False if neither split point's sign is certain: f too flat there to narrow
// (nearly coplanar for a while).
bool halve_at_root(const Bernstein& f, Piece& p) {
  for (const double s : {0.5, 7.0 / 16}) {
    Piece left, right;
    split(p, s, left, right);
    const double err = bound(f, left.depth);
    const int s0 = sign_beyond(left.b[0], err), sm = sign_beyond(left.b[3], err);
    if (s0 == 0 || sm == 0) continue;
    p = s0 != sm ? left : right;
    return true;
  }
  return false;
}

// f's root in the piece p (certain opposite signs at its ends), roughly, in p's own parameter:
// Newton steps on its Bernstein form, kept inside a bracket that is halved instead when a step
// leaves it. Where to look and to bracket: never part of a verdict by itself.
double rough_root(const Piece& p) {
  const double* b = p.b;
  const bool rising = b[0] < 0;
  double lo = 0, hi = 1, u = b[0] / (b[0] - b[3]);
  for (int i = 0; i < 12; ++i) {
    const double r = 1 - u, a0 = r * b[0] + u * b[1], a1 = r * b[1] + u * b[2],
                 a2 = r * b[2] + u * b[3], c0 = r * a0 + u * a1, c1 = r * a1 + u * a2;
    const double value = r * c0 + u * c1, slope = 3 * (c1 - c0);
    ((value < 0) == rising ? lo : hi) = u;
    const double next = u - value / slope;
    if (next == u) break;  // converged: u may sit on the bracket's end it just set
    u = next > lo && next < hi ? next : (lo + hi) / 2;  // a NaN step halves too
  }
  return u;
}

// s in (0, 1), moved by at most one rounding so that 1 - s is exact too, as split() needs:
// 1 - s is exact for s >= 1/2 (Sterbenz), and so is 1 - r for r = fl(1 - s) in [1/2, 1].
double exact_complement(double s) {
  return s >= 0.5 ? s : 1 - (1 - s);
}

// Narrows p (one simple root: one sign variation, certain opposite signs at its ends) to about
// 2^-32 around the rough root at u (p's own parameter) with two splits instead of some thirty
// halvings: f's signs certain at both new ends and equal to those at p's ends put the root
// between them. False, p unchanged, where a sign there is uncertain or not as expected.
bool bracket_root(const Bernstein& f, Piece& p, double u) {
  const double h = 0x1p-33 / (p.hi - p.lo);
  if (!(u - h > 0 && u + h < 1)) return false;
  Piece left, right, mid, rest;
  const double s1 = exact_complement(u - h);
  split(p, s1, left, right);
  const double s2 = exact_complement((u + h - s1) / (1 - s1));
  if (!(s2 > 0 && s2 < 1)) return false;
  split(right, s2, mid, rest);
  const double err = bound(f, mid.depth), err_p = bound(f, p.depth);
  const int s0 = sign_beyond(mid.b[0], err), s3 = sign_beyond(mid.b[3], err);
  if (s0 == 0 || s3 == 0 || s0 != sign_beyond(p.b[0], err_p) || s3 != sign_beyond(p.b[3], err_p))
    return false;
  p = mid;
  return true;
}

// Each condition at t with every coordinate difference, product and sum taken in absolute
// value, each difference first widened by `delta`: with delta = 0 its rounding error is some
// eps times that; the growth from delta = 2^-49 X (X the largest |coordinate|: what rounding
// pushes the positions' intervals by) is, to first order, what the intervals widen it by even
// over a single instant. A condition tiny only because its vectors are short is not noise;
// one tiny because the edges are nearly parallel (their cross product is noise) is.
V3<double> abs3(const V3<double>& v, double delta) {
  return {std::fabs(v.x) + delta, std::fabs(v.y) + delta, std::fabs(v.z) + delta};
}
V3<double> cross_abs(const V3<double>& a, const V3<double>& b) {
  return {a.y * b.z + a.z * b.y, a.z * b.x + a.x * b.z, a.x * b.y + a.y * b.x};
}
Conditions<double> magnitudes(const V3<double> x[4], QueryKind kind, double delta) {
  if (kind == QueryKind::VertexFace) {  // x0 the point, x1 x2 x3 the triangle
    const V3<double> a = abs3(x[1] - x[0], delta), b = abs3(x[2] - x[0], delta),
                     c = abs3(x[3] - x[0], delta),
                     n = cross_abs(abs3(x[2] - x[1], delta), abs3(x[3] - x[1], delta));
    return {{dot(n, cross_abs(b, c)), dot(n, cross_abs(c, a)), dot(n, cross_abs(a, b))}, 3};
  }
  const V3<double> ea = abs3(x[1] - x[0], delta), eb = abs3(x[3] - x[2], delta),
                   w = abs3(x[2] - x[0], delta), m = cross_abs(ea, eb);
  const double mm = dot(m, m), s = dot(cross_abs(w, eb), m), u = dot(cross_abs(w, ea), m);
  return {{s, mm + s, u, mm + u}, 4};
}

// How wide the intervals of each condition are at t at the least (see magnitudes()); with
// `half` > 0, roughly how wide over [t - half, t + half]: each difference of positions then
// spread by 2 half times the largest |motion| of a coordinate.
Conditions<double> noise_at(const Query& q, double t, double half = 0) {
  V3<double> x[4];
  double big = 0, motion = 0;
  for (int i = 0; i < 4; ++i) {
    x[i] = at(q.x[i], q.x[i + 4], t);
    big = std::max({big, std::fabs(x[i].x), std::fabs(x[i].y), std::fabs(x[i].z)});
    const Vec3 d = q.x[i + 4] - q.x[i];
    motion = std::max({motion, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
  }
  Conditions<double> wide = magnitudes(x, q.kind, 0x1p-49 * big + 2 * half * motion);
  const Conditions<double> exact = magnitudes(x, q.kind, 0);
  for (int i = 0; i < wide.n; ++i) wide.g[i] = wide.g[i] - exact.g[i] + 0x1p-48 * exact.g[i];
  return wide;
}

// Whether intervals at the instant t could settle anything, by a plain look against the
// noise (noise_at): 1 if every condition is above it (inside), -1 if some is below minus it
// (outside), 0 if neither, where the intervals would almost surely fail as well.
int beyond_noise(const Query& q, double t) {
  const Conditions<double> c = conditions_at(q, t), noise = noise_at(q, t);
  bool inside = true;
  for (int i = 0; i < c.n; ++i) {
    if (c.g[i] < -noise.g[i]) return -1;
    inside &= c.g[i] > noise.g[i];
  }
  return inside ? 1 : 0;
}

// True if intervals of width about 2 w around t would certainly fail: no condition keeps one
// sign clearly (its value at t more than four times its change from t - w to t + w, roughly
// what the intervals widen it by) where it is < 0, and some condition does not where it is > 0.
// A condition of tiny size but steady sign still counts: sizes differ by many orders.
bool hopeless_at(const Query& q, double t, double w) {
  const Conditions<double> c = conditions_at(q, t), before = conditions_at(q, t - w),
                           after = conditions_at(q, t + w);
  bool unsteady = false;
  for (int i = 0; i < c.n; ++i) {
    const bool steady = std::fabs(c.g[i]) > 4 * std::fabs(after.g[i] - before.g[i]);
    if (steady && c.g[i] < 0) return false;
    unsteady |= !steady;
  }
  return unsteady;
}

// The root of f isolated in `p` (one sign variation, f(lo) f(hi) < 0), p narrowed in place to
// where the conditions were evaluated: narrowed to about 2^-32
// around the rough root, else by halving to 2^-32 wide (or until the halving point's sign is
// uncertain), then the conditions g_i over the piece, once: certain signs there settle this
// root wherever it is in the piece. On the
// benchmark sample, the hard and the generic families, 2^-27 decides as many queries as 2^-40
// (2^-24 fewer), and deciding at 2^-20 before narrowing further decided no more but cost a
// second evaluation where it failed.
Filtered contact_at_root(const Query& q, const Bernstein& f, Piece& p, int& evaluations) {
  // A condition about 0 at the root, none clearly < 0: the point slides on an edge, or the
  // edges touch at an end; the intervals would straddle 0. Given up before narrowing.
  const double u = rough_root(p);
  if (hopeless_at(q, p.lo + u * (p.hi - p.lo), 0x1p-32)) return Filtered::Uncertain;
  if (p.hi - p.lo > 0x1p-32 && !bracket_root(f, p, u))
    while (p.hi - p.lo > 0x1p-32 && halve_at_root(f, p)) {
    }
  if (++evaluations > kMaxEvaluations) return Filtered::Uncertain;
  const Signs c = certain_signs(conditions(q, p));
  return c.out ? Filtered::No : (c.inside ? Filtered::Yes : Filtered::Uncertain);
}

// True if some condition is certainly < 0 over the whole piece: no contact in it, whatever f.
bool outside(const Query& q, const Piece& p) {
  return certain_signs(conditions(q, p)).out;
}

// Whether, by a plain floating-point look, some condition is clearly < 0 in p's middle and at
// both its ends (the middle first: most often it is not), clearly meaning below -2^-20 of the
// largest condition at any of the three: where all are tiny in the middle only (nearly
// parallel edges there), the intervals over the piece are as wide as at the ends; and in the
// middle below minus its noise (noise_at), spread over `spread` of the piece on either side.
bool negative_throughout(const Query& q, const Piece& p, double spread) {
  const auto negative = [](const Conditions<double>& c, double size) {
    unsigned which = 0;
    for (int i = 0; i < c.n; ++i) which |= unsigned(c.g[i] < -0x1p-20 * size) << i;
    return which;
  };
  const double t = p.lo + 0.5 * (p.hi - p.lo);
  const Conditions<double> mid = conditions_at(q, t);
  if (negative(mid, size_of(mid)) == 0) return false;
  const Conditions<double> lo = conditions_at(q, p.lo), hi = conditions_at(q, p.hi);
  const double size = std::max({size_of(mid), size_of(lo), size_of(hi)});
  unsigned which = negative(mid, size) & negative(lo, size) & negative(hi, size);
  if (which == 0) return false;  // the noise last: it costs two looks
  const Conditions<double> noise = noise_at(q, t, spread * (p.hi - p.lo));
  for (int i = 0; i < mid.n; ++i) which &= ~(unsigned(-mid.g[i] <= noise.g[i]) << i);
  return which != 0;
}

// A piece of [0, 1] that may hold a root of f, kept for later.
struct Stack {
  static constexpr int kMaxDepth = 8;
  Piece piece[kMaxDepth + 2];
  int top = 0;
  void push(const Piece& p) { piece[top++] = p; }
};

// Whether four points lie exactly in one plane: all in a plane x = c (or y, or z), or their
// volume exactly 0 (orient3d_exact.hpp; it declines where a difference is not exact).
bool exactly_coplanar(const Vec3* x) {
  const auto same = [x](double Vec3::*axis) {
    return x[0].*axis == x[1].*axis && x[0].*axis == x[2].*axis && x[0].*axis == x[3].*axis;
  };
  int volume = 1;
  return same(&Vec3::x) || same(&Vec3::y) || same(&Vec3::z) ||
         (exact_volume_sign(x[0], x[1], x[2], x[3], volume) && volume == 0);
}

// How thin a sliver of p at `end` to try first, as 2^-k of the piece: over it, a condition
// certainly < 0 at `end` should stay < 0, for a quarter of |g| / |g'| (its slope estimated in
// floating point: a choice, not part of a verdict). k from 10 to 40.
int sliver_exponent(const Query& q, const Piece& p, double end,
                    const Conditions<Interval>& at_end) {
  const double w = p.hi - p.lo, step = 0x1p-20 * w;
  const Conditions<double> c0 = conditions_at(q, end),
                           c1 = conditions_at(q, end == 0 ? step : 1 - step);
  double reach = 0;  // as a fraction of the piece
  for (int i = 0; i < c0.n; ++i)
    if (at_end.g[i].negative())
      reach =
          std::max(reach, 0.25 * std::fabs(c0.g[i]) * step / (std::fabs(c0.g[i] - c1.g[i]) * w));
  return reach >= 0x1p-10 ? 10 : (reach > 0x1p-40 ? -std::ilogb(reach) : 40);  // NaN: 40
}

// Cuts off the sliver 2^-k of p at `end` (s and 1 - s exact, as split() needs) and pushes the
// rest if some condition is certainly < 0 over the sliver. Else, once, a thinner sliver: by as
// much as the widest interval of a condition < 0 at `end` exceeds its size there (interval
// bounds widen in proportion to the time interval).
bool cut_sliver(const Query& q, const Piece& p, double end, const Conditions<Interval>& at_end,
                Stack& stack, int& evaluations) {
  for (int k = sliver_exponent(q, p, end, at_end), attempt = 0;; ++attempt) {
    const double s = std::ldexp(1.0, -k);
    Piece left, right;
    split(p, end == 0 ? s : 1 - s, left, right);
    const Conditions<Interval> c = conditions(q, end == 0 ? left : right);
    double widest = 0;
    for (int i = 0; i < c.n; ++i) {
      if (c.g[i].negative()) {
        stack.push(end == 0 ? right : left);
        return true;
      }
      if (at_end.g[i].negative())
        widest = std::max(widest, (c.g[i].hi - c.g[i].lo) / -at_end.g[i].hi);
    }
    k += std::ilogb(widest) + 2;
    if (attempt == 1 || !(k <= 50) || ++evaluations > kMaxEvaluations) return false;
  }
}

// The piece p ends at t = `end` (0 or 1) and f's sign there is uncertain: a contact may sit
// exactly at the start or the end. Settled here where floating point can settle it: the
// conditions at the very instant `end`, bounded by intervals (tight there), say whether the
// point (or the edges' crossing) is then inside; an exact sum of the volume (orient3d_exact.hpp)
// says whether the four points are then coplanar. Inside and coplanar: a contact (yes). Some
// condition certainly < 0 at `end`: none at that instant, nor, when the intervals confirm it,
// on a sliver of the piece at that end (cut_sliver); the rest is pushed back for the search,
// unless only a contact is asked for (a piece where f is flat throughout: the rest would be no
// better). Otherwise uncertain.
// `look` is look_at(q, end).
Filtered settle_end(const Query& q, const Piece& p, double end, const Look& look, bool contact_only,
                    Stack& stack, int& evaluations) {
  // (look.hopeless(0x1p-40) was settled by the caller.)
  if ((contact_only && look.lowest <= 0x1p-20) || ++evaluations > kMaxEvaluations)
    return Filtered::Uncertain;
  if (beyond_noise(q, end) == 0) return Filtered::Uncertain;
  const Conditions<Interval> c = conditions_at(q, Interval{end, end});
  const Signs signs = certain_signs(c);
  if (signs.inside)
    return exactly_coplanar(&q.x[end == 0 ? 0 : 4]) ? Filtered::Yes : Filtered::Uncertain;
  if (!signs.out || contact_only || p.depth == Stack::kMaxDepth || ++evaluations > kMaxEvaluations)
    return Filtered::Uncertain;
  return cut_sliver(q, p, end, c, stack, evaluations) ? Filtered::No : Filtered::Uncertain;
}

// 0 or 1 if f's sign is uncertain at that end of [0, 1] and p reaches it (0 first), else -1.
int open_end(const Piece& p, double err) {
  if (p.lo == 0 && sign_beyond(p.b[0], err) == 0) return 0;
  return p.hi == 1 && sign_beyond(p.b[3], err) == 0 ? 1 : -1;
}

// A piece where f's sign is uncertain (v < 0): No if it holds no contact (drop it), Yes or
// Uncertain for the whole query, none to split it further.
std::optional<Filtered> uncertain_piece(const Query& q, const Piece& p, double err, Stack& stack,
                                        int& evaluations) {
  // f's sign uncertain at t = 0 or 1 (see below): where a condition is about 0 there and
  // none clearly < 0, settle_end gives up, and none is clearly < 0 throughout either (the
  // test below would look at that end too): given up at once, one look sooner.
  const int end = open_end(p, err);
  const Look look = end < 0 ? Look{} : look_at(q, end);
  if (end >= 0 && look.hopeless(0x1p-40)) return Filtered::Uncertain;
  // f's sign is uncertain somewhere here (f may even vanish throughout, as for a cube
  // sliding on a plane): a condition certainly < 0 over the whole piece still excludes it.
  // Only where some condition is clearly < 0 at both ends and in the middle: else none is
  // < 0 throughout, or the intervals would be too wide to show it.
  // Where nothing else could decide (f flat on the piece, and settle_end would give up at
  // its end), the intervals over the piece are paid for only where the condition in the
  // middle clears their rough width over the middle quarter: on the sliding-on-edge and
  // coplanar families these evaluations almost all fail, and a few decisions are lost.
  const bool is_flat = flat(p, err);
  const bool last_chance = is_flat && (end < 0 ? p.lo != 0 && p.hi != 1 : look.lowest <= 0x1p-20);
  if (negative_throughout(q, p, last_chance ? 0.125 : 0)) {
    if (++evaluations > kMaxEvaluations) return Filtered::Uncertain;
    if (outside(q, p)) return Filtered::No;
  }
  // Smaller pieces would not show a sign either where f may vanish on the whole piece (no
  // coefficient certain: coplanar motion): the exact test decides. Nor at t = 0 or 1 when
  // its first or last one is uncertain there: settle_end decides what it can.
  // Where it is flat at t = 0 or 1 too, a contact right there is still worth a look
  // (coplanar motion that starts or ends inside the triangle): settle_end, for a yes only.
  if (is_flat && p.lo != 0 && p.hi != 1) return Filtered::Uncertain;
  if (end >= 0) return settle_end(q, p, end, look, is_flat, stack, evaluations);
  return std::nullopt;
}

// ---- The time of impact: what the search learns of the earliest contact t*.

// A piece's true ends, outward, as doubles: its rounded ends lie within its slack of them
// (slack >= 2^-51 beyond depth 0, so the subtraction's own rounding stays inside).
double lo_of(const Piece& p) {
  return p.depth == 0 ? p.lo : std::max(0.0, p.lo - 2 * p.slack);
}
double hi_of(const Piece& p) {
  return p.depth == 0 ? p.hi : std::min(1.0, p.hi + 2 * p.slack);
}

// f's Bernstein coefficients again, in extended precision (long double: 64 bits of mantissa on
// x86; where it is no wider than double, the narrowing below merely gives up sooner), with the
// same derivation of the error bound (orient3d_filter.hpp) at that precision's unit roundoff.
using Wide = long double;
constexpr Wide kWideEps = std::numeric_limits<Wide>::epsilon() / 2;

struct WideBernstein {
  Wide b[4];
  Wide err;  // bounds |de Casteljau's value - f(t)| at any double t in [0, 1] (see sign())
  // f's sign at the double t, where certain: de Casteljau's three levels of (1 - t) x + t y,
  // 1 - t rounded at most once, are off by < 16 u times the largest |coefficient| (split()).
  int sign(double t) const {
    const Wide v = value(t);
    return v > err ? 1 : (-v > err ? -1 : 0);
  }
  Wide value(double t, Wide* slope = nullptr) const {
    const Wide s = t, r = 1 - s;
    const Wide a0 = r * b[0] + s * b[1], a1 = r * b[1] + s * b[2], a2 = r * b[2] + s * b[3];
    const Wide c0 = r * a0 + s * a1, c1 = r * a1 + s * a2;
    if (slope) *slope = 3 * (c1 - c0);
    return r * c0 + s * c1;
  }
};

V3<Wide> wide(const Vec3& a, const Vec3& b) {  // b - a, in extended precision
  return {Wide(b.x) - a.x, Wide(b.y) - a.y, Wide(b.z) - a.z};
}

// As bernstein(): the coefficients off by kOrient3dMeanOfThreeErrBound's 72 u P, evaluation
// by 16 u (6 P + that) more.
WideBernstein wide_bernstein(const Query& q) {
  const auto& x = q.x;
  const V3<Wide> u[2] = {wide(x[0], x[1]), wide(x[4], x[5])},
                 v[2] = {wide(x[0], x[2]), wide(x[4], x[6])},
                 w[2] = {wide(x[0], x[3]), wide(x[4], x[7])};
  Wide mx = 0, my = 0, mz = 0;
  for (const V3<Wide>* s : {u, v, w})
    for (int i = 0; i < 2; ++i)
      mx = std::max(mx, std::fabs(s[i].x)), my = std::max(my, std::fabs(s[i].y)),
      mz = std::max(mz, std::fabs(s[i].z));
  const auto det = [](const V3<Wide>& a, const V3<Wide>& b, const V3<Wide>& c) {
    return dot(a, cross(b, c));
  };
  WideBernstein r{};
  r.b[0] = det(u[0], v[0], w[0]);
  r.b[1] = (det(u[1], v[0], w[0]) + det(u[0], v[1], w[0]) + det(u[0], v[0], w[1])) / 3;
  r.b[2] = (det(u[1], v[1], w[0]) + det(u[1], v[0], w[1]) + det(u[0], v[1], w[1])) / 3;
  r.b[3] = det(u[1], v[1], w[1]);
  const Wide p = mx * my * mz, coefficients = 72 * kWideEps * p;
  r.err = coefficients + 16 * kWideEps * (6 * p + coefficients);
  return r;
}

// Narrows [a, b], which holds f's root r isolated in p (f's sign at p's true lower end is
// s_lo), to `width` with a > 0 (t_lo = 0 only when t* = 0): a certain sign of f at a double m
// inside p's true ends puts m on one side of r. Newton steps in extended precision guess r; two
// probes a quarter of the width either side bracket it, else the middle halves [a, b]. False where
// no sign is certain any more.
bool narrow_root(const Query& q, const Piece& p, int s_lo, double width, double& a, double& b) {
  if constexpr (std::numeric_limits<Wide>::digits <= 53) return false;  // no wider than f
  // Coordinates within 2^100 (robust_ccd_toi_filter) and x87's exponent range: no overflow,
  // and products of doubles' differences (>= 2^-3300) never underflow.
  const WideBernstein f = wide_bernstein(q);
  // (0 and 1 are exact ends: a piece's ends are rounded only where a split cut it.)
  const double in_lo = p.lo == 0 ? 0 : p.lo + 2 * p.slack,
               in_hi = p.hi == 1 ? 1 : p.hi - 2 * p.slack;
  double guess = p.lo + rough_root(p) * (p.hi - p.lo);
  for (int i = 0; i < 3; ++i) {
    Wide slope;
    const Wide v = f.value(guess, &slope), next = guess - v / slope;
    if (!(next > a && next < b)) break;
    guess = double(next);
  }
  // f(0) != 0 here (a root isolated at 0 has no certain sign there), so t* > 0 and so is a.
  for (int step = 0; step < 64 && (b - a > width || a == 0); ++step) {
    const double h = width / 4;
    const bool near = guess - h > a && guess + h < b;
    const double probe[2] = {near ? guess - h : a + (b - a) / 2, guess + h};
    bool moved = false;
    for (int i = 0; i < (near ? 2 : 1); ++i) {
      const double m = probe[i];
      if (!(m > a && m < b && m >= in_lo && m <= in_hi)) continue;
      const int s = f.sign(m);
      if (s != 0) (s == s_lo ? a : b) = m, moved = true;
    }
    if (!moved) return false;
  }
  return b - a <= width && a > 0;
}

// What subdivide() learns of t* on its way, for robust_ccd_toi_filter.
struct ToiTrack {
  double width;
  double open = 2;  // the earliest true end of a piece left open (2: none), outward
  FilteredToi out;

  void open_piece(const Piece& p) { open = std::min(open, lo_of(p)); }

  // The search ends on p with `verdict`; with a contact at t = `end` (0 or 1) if end >= 0.
  void settled(Filtered verdict, const Piece& p, int end) {
    open_piece(p);
    out = verdict == Filtered::Yes && end == 0 ? FilteredToi{verdict, 0, 0, true}  // t* = 0
                                               : FilteredToi{verdict, open, 1, false};
  }

  // A contact at f's root r isolated in p (f's sign s_lo at p's lower end): where no piece
  // before p was left open, t* = r.
  void contact_at_root(const Query& q, const Piece& p, int s_lo) {
    out.t1 = hi_of(p);
    if (open < 2) {
      out.t0 = open;
      return;
    }
    out.t0 = lo_of(p);
    out.enclosed =
        (out.t1 - out.t0 <= width && out.t0 > 0) || narrow_root(q, p, s_lo, width, out.t0, out.t1);
  }
};

// Stage 2: isolate the roots of f in [0, 1] by Bernstein subdivision (a piece whose
// coefficients are certain and of one sign holds no root; one sign variation with
// f(lo) f(hi) < 0 holds exactly one simple root), then decide the contact at each root.
// Pieces are taken in time order (left before right), so with `toi`, every piece before the
// current one has been excluded or recorded as open (ToiTrack).
Filtered subdivide(const Query& q, const Bernstein& f, ToiTrack* toi = nullptr) {
  constexpr int kMaxPieces = 12;
  Stack stack;
  int pieces = 0, evaluations = 0;
  stack.push({0, 1, 0, {f.b[0], f.b[1], f.b[2], f.b[3]}, 0});
  bool uncertain = false;
  while (stack.top > 0) {
    const Piece p = stack.piece[--stack.top];
    const double err = bound(f, p.depth);
    const int v = variations(p, err);
    if (v == 0) continue;  // one certain sign: no root here
    if (v < 0) {           // f's sign uncertain somewhere in p
      const std::optional<Filtered> r = uncertain_piece(q, p, err, stack, evaluations);
      if (r == Filtered::No) continue;  // nothing in p
      if (r) {
        if (toi) toi->settled(*r, p, open_end(p, err));
        return *r;
      }
    }
    if (v == 1 && sign_beyond(p.b[0], err) != sign_beyond(p.b[3], err)) {
      Piece root = p;
      const Filtered r = contact_at_root(q, f, root, evaluations);
      if (r == Filtered::Yes) {
        if (toi) toi->contact_at_root(q, root, sign_beyond(p.b[0], err));
        return r;
      }
      if (r == Filtered::Uncertain && toi) toi->open_piece(p);
      uncertain |= r == Filtered::Uncertain;
      continue;
    }
    if (p.depth == Stack::kMaxDepth || ++pieces > kMaxPieces) {
      if (toi) toi->open_piece(p);
      uncertain = true;
      continue;
    }
    // Not the middle: handcrafted contacts sit at t = 1/2, 1/4, ..., and a piece that ends on
    // a root never shows a certain sign there.
    Piece left, right;
    split(p, 7.0 / 16, left, right);
    stack.push(right);
    stack.push(left);
  }
  return uncertain ? Filtered::Uncertain : Filtered::No;
}

// Within δ = q.min_distance > 0 (docs/methods.md, "Minimum separation: the robust filter"):
// f of one certain sign bounds the distance to the plane (or between the lines) from below, and
// a certain contact is within δ (its time bounds t*_δ from above); the time search
// (ccd_robust_delta.cpp) decides what those leave.
FilteredToi within_delta(const Query& q, const Bernstein& f, double width) {
  if (!(q.min_distance <= 0x1p100)) return {};
  double lowest = HUGE_VAL;
  for (const double b : f.b) lowest = std::min(lowest, std::fabs(b));
  const int sign = bernstein_sign(f);
  if (sign != 0 && apart_by_volume(q, round_down(lowest - f.err)))
    return {Filtered::No, 1, 1, false};
  double contact_by = 2;
  if (sign == 0) {
    ToiTrack toi{1, 2, {}};  // its t1 only: a contact by then (no narrowing: width 1)
    if (subdivide(q, f, &toi) == Filtered::Yes) {
      if (width <= 0) return {Filtered::Yes, 0, 1, false};
      contact_by = toi.out.t1;
    }
  }
  return robust_delta_search(q, width, contact_by);
}

// Stage 3 (ccd_robust_integer.hpp): its No, and its Yes with the earliest contact enclosed when
// `want_time` (else not enclosed: the exact fallback finds the time).
FilteredToi integer_stage(const Query& q, bool want_time, RobustStage& stage) {
  const IntegerToi r = robust_ccd_integer(q, want_time);
  if (r.verdict == Filtered::Uncertain) return {};
  stage = RobustStage::Integer;
  if (r.verdict == Filtered::No) return {Filtered::No, 1, 1, false};
  return r.exact ? FilteredToi{Filtered::Yes, r.t_lo, r.t_hi, true} : FilteredToi{Filtered::Yes};
}

// robust_ccd_toi_filter, telling `stage` which stage decided (else RobustStage::Exact).
FilteredToi filter(const Query& q, double width, RobustStage& stage) {
  // Interval bounds never overflow below 2^100: the conditions have degree 4 in coordinates.
  for (const Vec3& v : q.x)
    if (!(std::fabs(v.x) <= 0x1p100 && std::fabs(v.y) <= 0x1p100 && std::fabs(v.z) <= 0x1p100))
      return {};
  // Both kinds: f = det(x1 - x0, x2 - x0, x3 - x0), at t = 0 and t = 1.
  const auto& x = q.x;
  const Vec3 u[2] = {x[1] - x[0], x[5] - x[4]}, v[2] = {x[2] - x[0], x[6] - x[4]},
             w[2] = {x[3] - x[0], x[7] - x[4]};
  const Bernstein f = bernstein(u, v, w);
  if (!f.valid) return {};
  stage = RobustStage::Subdivision;
  if (q.min_distance > 0) return within_delta(q, f, width);
  if (bernstein_sign(f) != 0) {
    stage = RobustStage::Volume;
    return {Filtered::No, 1, 1, false};
  }
  // f about 0 throughout (no coefficient of certain sign: coplanar motion): the subdivision
  // would give up, so the integer stage goes first.
  const Piece whole{0, 1, 0, {f.b[0], f.b[1], f.b[2], f.b[3]}, 0};
  const bool flat_f = flat(whole, f.err);
  if (width <= 0) {
    const FilteredToi r = flat_f ? integer_stage(q, false, stage) : FilteredToi{};
    if (r.verdict != Filtered::Uncertain) return r;
    const Filtered verdict = subdivide(q, f);
    return verdict != Filtered::Uncertain || flat_f ? FilteredToi{verdict, 0, 1, false}
                                                    : integer_stage(q, false, stage);
  }
  if (flat_f) {
    const FilteredToi r = integer_stage(q, true, stage);
    if (r.verdict == Filtered::No || r.enclosed) return r;
  }
  ToiTrack toi{width, 2, {}};
  const Filtered verdict = subdivide(q, f, &toi);
  if (verdict == Filtered::No) return {Filtered::No, 1, 1, false};
  toi.out.verdict = verdict;
  if (verdict == Filtered::Yes) return toi.out;
  toi.out.t0 = std::min(toi.open, 1.0), toi.out.t1 = 1;
  const FilteredToi exact = flat_f ? FilteredToi{} : integer_stage(q, true, stage);
  return exact.verdict == Filtered::No || exact.enclosed ? exact : toi.out;
}

}  // namespace

Filtered robust_ccd_filter(const Query& q) {
  return robust_ccd_toi_filter(q, 0).verdict;
}

FilteredToi robust_ccd_toi_filter(const Query& q, double width) {
  RobustStage stage;
  return filter(q, width, stage);
}

RobustStage robust_ccd_stage(const Query& q) {
  RobustStage stage = RobustStage::Exact;
  const FilteredToi f = filter(q, 0, stage);
  return f.verdict == Filtered::Uncertain ? RobustStage::Exact : stage;
}

}  // namespace fdh
