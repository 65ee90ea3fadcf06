#include "ccd_robust_delta.hpp"

#include <algorithm>
#include <cmath>

#include "fdh/closest_points.hpp"
#include "fdh/interval.hpp"
#include "motion.hpp"

namespace fdh {
namespace {

using namespace motion;
using IV3 = V3<Interval>;

// δ² as an interval: lo <= δ² <= hi.
Interval delta_squared(const Query& q) {
  const Interval d = Interval::point(q.min_distance);
  return d * d;
}

// The first point of the second primitive: the triangle's (vertex-face) or edge b's (edge-edge).
int first_of_b(const Query& q) {
  return q.kind == QueryKind::VertexFace ? 1 : 2;
}

// ---- Plain floating point at one instant: where to look, never a verdict by itself.

Vec3 at_time(const Vec3& x0, const Vec3& x1, double t) {
  return x0 + t * (x1 - x0);
}
using Closest = ClosestPoints;

Closest closest_at(const Query& q, double t) {
  Vec3 x[4];
  for (int i = 0; i < 4; ++i) x[i] = at_time(q.x[i], q.x[i + 4], t);
  return q.kind == QueryKind::VertexFace ? closest_point_triangle(x[0], x[1], x[2], x[3])
                                         : closest_segments(x[0], x[1], x[2], x[3]);
}

// The closest pair's motion over the step (its points' displacements, at the same parameters).
Vec3 relative_motion(const Query& q, const Closest& c) {
  Vec3 d[4];
  for (int i = 0; i < 4; ++i) d[i] = q.x[i + 4] - q.x[i];
  if (q.kind == QueryKind::VertexFace)
    return d[0] - (d[1] + c.s * (d[2] - d[1]) + c.u * (d[3] - d[1]));
  return (d[0] + c.s * (d[1] - d[0])) - (d[2] + c.u * (d[3] - d[2]));
}

// From t, a time in [lo, hi] where the distance is least nearby, in plain doubles: the zero of
// h = dir . v, half the derivative of the squared distance (the closest pair's parameters are
// optimal, so their own change does not count: the envelope theorem), by one Newton step that
// keeps the parameters (h' ~ |v|²), then secant steps. Never part of a verdict by itself.
double nearest_time(const Query& q, Closest c, double t, double lo, double hi) {
  const Vec3 v = relative_motion(q, c);
  double h = dot(c.dir, v), next = t - h / dot(v, v);
  for (int i = 0; i < 4 && c.dist2 > 0; ++i) {
    const double clamped = std::min(hi, std::max(lo, next));  // NaN: stays
    if (!(clamped != t)) break;
    const double t_prev = t, h_prev = h;
    t = clamped, c = closest_at(q, t), h = dot(c.dir, relative_motion(q, c));
    next = t - h * (t - t_prev) / (h - h_prev);
  }
  return t;
}

// ---- Rigorous bounds: intervals (fdh/interval.hpp) around the exact positions.

// A coordinate at the double t, enclosed: v = x0 + t (x1 - x0) in three roundings is off by at
// most eps |v| + 2.01 eps |t (x1 - x0)| (the difference's and the product's relative errors
// carried by the product), 2^-52 (|v| + 3 |m|) allowing for more, and 2^-1070 for an
// underflowed product. A third of an interval lerp's cost.
Interval coordinate_at(double x0, double x1, double t) {
  const double m = t * (x1 - x0), v = x0 + m;
  const double err = (std::fabs(v) + 3 * std::fabs(m)) * 0x1p-52 + 0x1p-1070;
  return {round_down(v - err), round_up(v + err)};
}

// The four points at the double t, enclosed.
struct Points {
  IV3 x[4];
};
Points points_at(const Query& q, double t) {
  Points r;
  for (int i = 0; i < 4; ++i) {
    const Vec3 &a = q.x[i], &b = q.x[i + 4];
    r.x[i] = {coordinate_at(a.x, b.x, t), coordinate_at(a.y, b.y, t), coordinate_at(a.z, b.z, t)};
  }
  return r;
}

IV3 point3(const Vec3& v) {
  return {Interval::point(v.x), Interval::point(v.y), Interval::point(v.z)};
}

// Whether s + u <= 1 exactly (s, u >= 0): the rounded sum decides unless it is 1, where its
// rounding error (Knuth's TwoSum, exact) does.
bool at_most_one(double s, double u) {
  const double sum = s + u;
  if (sum != 1) return sum < 1;
  const double uu = sum - s;
  return (s - (sum - uu)) + (u - uu) <= 0;
}

// Certain: the distance at t is <= δ. The pair the closest point c names is a pair of points of
// the two closed primitives (its parameters checked to be convex weights, exactly): their
// distance, rounded up, is an upper bound of the primitives'.
bool within_at(const Query& q, const Interval& d2, const Points& p, Closest c) {
  if (!(c.s >= 0 && c.u >= 0)) return false;
  // Rounded barycentric coordinates may sum to a hair above 1: the larger gives way.
  if (q.kind == QueryKind::VertexFace && !at_most_one(c.s, c.u))
    (c.s >= c.u ? c.s : c.u) = 1 - (c.s >= c.u ? c.u : c.s);
  const Interval s = Interval::point(c.s), u = Interval::point(c.u);
  IV3 diff;
  if (q.kind == QueryKind::VertexFace) {
    if (!at_most_one(c.s, c.u)) return false;
    diff = p.x[0] - (p.x[1] + s * (p.x[2] - p.x[1]) + u * (p.x[3] - p.x[1]));
  } else {
    if (!(c.s <= 1 && c.u <= 1)) return false;
    diff = (p.x[0] + s * (p.x[1] - p.x[0])) - (p.x[2] + u * (p.x[3] - p.x[2]));
  }
  return dot(diff, diff).hi <= d2.lo;
}

// The range of a primitive's points over a time piece along one coordinate (or projection):
// each point moves linearly, so over [ta, tb] it lies between its values at the two ends, and the
// primitive, the convex hull of its points, between their least and greatest.
struct Range {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  void add(const Interval& v) { lo = std::min(lo, v.lo), hi = std::max(hi, v.hi); }
};

// A lower bound of the gap between the ranges of the first primitive (points [0, k)) and the
// second ([k, 4)), of `value` (a projection) of each point at the piece's two ends; <= 0: none.
template <class F>
double gap(const Points& a, const Points& b, int k, const F& value) {
  Range first, second;
  for (int i = 0; i < 4; ++i)
    for (const Points* p : {&a, &b}) (i < k ? first : second).add(value(p->x[i]));
  const double g1 = round_down(second.lo - first.hi), g2 = round_down(first.lo - second.hi);
  return std::max(g1, g2);
}

// Certain: the distance stays > δ over the piece whose ends' points are a and b. Two separating
// tests: the coordinate axes (the gaps of the two boxes, their squares summed), and `dir` (the
// closest pair's direction inside the piece): a gap g along dir keeps the primitives g / |dir|
// apart.
bool apart(const Query& q, const Interval& d2, const Points& a, const Points& b, const Vec3& dir) {
  const int k = first_of_b(q);
  double sum = 0;  // rounded down
  const auto axis = [&](Interval IV3::*c) {
    const double g = gap(a, b, k, [c](const IV3& v) { return v.*c; });
    if (g > 0) sum = round_down(sum + round_down(g * g));
  };
  axis(&IV3::x), axis(&IV3::y), axis(&IV3::z);
  if (sum > d2.hi) return true;
  const IV3 d = point3(dir);
  const double g = gap(a, b, k, [&d](const IV3& v) { return dot(d, v); });
  if (!(g > 0)) return false;
  const Interval gg = Interval::point(g) * Interval::point(g);
  return gg.lo > (d2 * dot(d, d)).hi;
}

// ---- The search.

// A piece of the window: its ends and depth only (the points at its ends are found again: an
// array of them would be zeroed on every call, costing more than the search).
struct Piece {
  double ta, tb;
  int depth;
};

constexpr int kMaxPieces = 24;  // pieces looked at per query, beyond which the exact test decides
constexpr int kMaxDepth = 30;   // a piece no narrower than 2^-30 of the window
constexpr int kMaxNarrowing = 64;

// Certain: the distance stays > δ over [a, b].
bool apart_over(const Query& q, const Interval& d2, double a, double b) {
  return apart(q, d2, points_at(q, a), points_at(q, b), closest_at(q, b).dir);
}
// Certain: the distance at t is <= δ.
bool within_at_time(const Query& q, const Interval& d2, double t) {
  const Closest c = closest_at(q, t);
  return c.dist2 <= d2.hi && within_at(q, d2, points_at(q, t), c);
}

// A guess of t*_δ in [a, b] (the distance > δ at a, <= δ at b), in plain doubles: Newton steps
// on distance - δ from b (its derivative is h / distance, h as in nearest_time()), kept inside
// the bracket, which a step that leaves it halves instead; until a step moves less than
// `width` / 8. Where to probe, never part of a verdict.
double guess_time(const Query& q, double delta, double a, double b, double width) {
  double t = b;
  for (int i = 0; i < 40; ++i) {
    const Closest c = closest_at(q, t);
    const double d = std::sqrt(c.dist2), phi = d - delta;
    (phi > 0 ? a : b) = t;
    double next = t - phi * d / dot(c.dir, relative_motion(q, c));
    if (!(next > a && next < b)) next = a + (b - a) / 2;  // NaN too
    if (std::fabs(next - t) < width / 8 || !(b - a > width / 8)) return next;
    t = next;
  }
  return t;
}

// The window [a, b] (no δ-contact in [0, a), one at b) narrowed to `width`: probes a quarter of
// the width either side of a guess of t*_δ (free up to the lower one, within δ at the upper),
// else halving, each middle m certainly free ([a, m] apart) or certainly within δ. The probe
// from a fails while [a, probe] is too long for one separating test: the halvings shorten it.
// Enclosed if it got there.
FilteredToi narrow(const Query& q, const Interval& d2, double a, double b, double width) {
  const double h = width / 4, g = guess_time(q, q.min_distance, a, b, width);
  for (int i = 0; i < kMaxNarrowing && (b - a > width || a == 0); ++i) {
    bool moved = false;
    if (g - h > a && g + h <= b) {
      if (g + h < b && within_at_time(q, d2, g + h)) b = g + h, moved = true;
      if (apart_over(q, d2, a, g - h)) a = g - h, moved = true;
      if (b - a <= width && a > 0) break;
    }
    const double m = a + (b - a) / 2;
    if (!(m > a && m < b)) break;
    if (apart_over(q, d2, a, m))
      a = m, moved = true;
    else if (within_at_time(q, d2, m))
      b = m, moved = true;
    if (!moved) break;
  }
  return {Filtered::Yes, a, b, b - a <= width && a > 0};
}

// What the search knows: δ², the width asked for, and the earliest piece left open (2: none).
struct Search {
  const Query& q;
  Interval d2;
  double width;
  double open = 2;
};

// A δ-contact at t = `hit`, inside the piece that starts at ta.
FilteredToi found(const Search& s, double ta, double hit) {
  if (s.width <= 0) return {Filtered::Yes, 0, 1, false};
  if (s.open < 2) return {Filtered::Yes, s.open, hit, false};
  return narrow(s.q, s.d2, ta, hit, s.width);
}

}  // namespace

bool apart_by_volume(const Query& q, double volume_lo) {
  // |f| / |n| is the distance of the vertex to the triangle's plane, or of the two edges' lines
  // (n = (b - a) x (c - a), or ea x eb; f = det(a - p, b - p, c - p) = (a - p) . n, or
  // det(ea, b0 - a0, b1 - a0) = (b0 - a0) . n): a lower bound of the primitives' distance
  // wherever n != 0, and f = 0 where n = 0. |n| <= |e1| |e2| for its two edge vectors, each of
  // which is linear in t, so largest at t = 0 or 1.
  // In plain doubles with relative margins: a rounded |e|² is below the exact one by at most
  // 6 eps of it (the differences' roundings counted twice, the squares' and sums' once), or
  // 2^-1070 where it underflows; (1 ± 2^-40) covers every relative rounding below, and 2^-600
  // every underflow (< 2^-1074 each, scaled by at most 2^406: coordinates and δ are within
  // 2^100).
  if (!(volume_lo > 0)) return false;
  const bool vf = q.kind == QueryKind::VertexFace;
  const int i1 = vf ? 1 : 0, j1 = i1 + 1, i2 = vf ? 1 : 2, j2 = 3;
  double n1 = 0, n2 = 0;
  for (const int t : {0, 4}) {
    const Vec3 e1 = q.x[j1 + t] - q.x[i1 + t], e2 = q.x[j2 + t] - q.x[i2 + t];
    n1 = std::max(n1, dot(e1, e1)), n2 = std::max(n2, dot(e2, e2));
  }
  const double d = q.min_distance;
  const double bound = (d * d) * (n1 + 0x1p-1070) * (n2 + 0x1p-1070) * (1 + 0x1p-40) + 0x1p-600;
  return volume_lo * volume_lo * (1 - 0x1p-40) > bound;
}

FilteredToi robust_delta_search(const Query& q, double width, double contact_by) {
  Search s{q, delta_squared(q), width};
  const Closest c0 = closest_at(q, 0);
  const Points p0 = points_at(q, 0);
  if (c0.dist2 <= s.d2.hi && within_at(q, s.d2, p0, c0)) return {Filtered::Yes, 0, 0, true};
  const double end = std::min(contact_by, 1.0);
  // Depth first, the earlier half on top: pieces in time order.
  Piece stack[kMaxDepth + 2];
  int top = 0, pieces = 0;
  stack[top++] = {0, end, 0};
  while (top > 0) {
    const Piece p = stack[--top];
    const double tm = p.ta + (p.tb - p.ta) / 2;
    const Closest c = closest_at(q, tm);
    if (apart(q, s.d2, p.ta == 0 ? p0 : points_at(q, p.ta), points_at(q, p.tb), c.dir)) continue;
    if (c.dist2 <= s.d2.hi && within_at(q, s.d2, points_at(q, tm), c)) return found(s, p.ta, tm);
    // Where the closest pair's motion brings it nearest inside the piece: a dip below δ there is
    // found at once, not after halving down to its width.
    const double tn = nearest_time(q, c, tm, p.ta, p.tb);
    if (tn != tm && within_at_time(q, s.d2, tn)) return found(s, p.ta, tn);
    if (p.depth == kMaxDepth || ++pieces > kMaxPieces || !(tm > p.ta && tm < p.tb)) {
      s.open = std::min(s.open, p.ta);
      continue;
    }
    stack[top++] = {tm, p.tb, p.depth + 1};
    stack[top++] = {p.ta, tm, p.depth + 1};
  }
  if (contact_by <= 1) return {Filtered::Yes, std::min(s.open, end), end, false};
  if (s.open < 2) return {Filtered::Uncertain, width > 0 ? s.open : 0, 1, false};
  return {Filtered::No, 1, 1, false};
}

}  // namespace fdh
