#include "fdh/ccd/robust.hpp"

#include "fdh/interval.hpp"
#include "fdh/orient3d_filter.hpp"

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
// Each vector is one rounded difference, so each determinant is off by at most 48 eps P with
// P = Mx My Mz the product of the largest |coordinates| over all six vectors (as in
// orient3d_filter.hpp); a sum of three is off by at most 3 x 48 eps P plus two roundings of at
// most 18 (1 + eps) P eps each: below 192 eps P.
int bernstein_sign(const Vec3 u[2], const Vec3 v[2], const Vec3 w[2]) {
  double mx = 0, my = 0, mz = 0;
  for (const Vec3* s : {u, v, w})
    for (int i = 0; i < 2; ++i) {
      const double ax = std::fabs(s[i].x), ay = std::fabs(s[i].y), az = std::fabs(s[i].z);
      mx = ax > mx ? ax : mx, my = ay > my ? ay : my, mz = az > mz ? az : mz;
    }
  if (!(in_filter_range(mx) && in_filter_range(my) && in_filter_range(mz))) return 0;
  const double p = mx * my * mz;
  const double b[4] = {
      det(u[0], v[0], w[0]), det(u[1], v[0], w[0]) + det(u[0], v[1], w[0]) + det(u[0], v[0], w[1]),
      det(u[1], v[1], w[0]) + det(u[1], v[0], w[1]) + det(u[0], v[1], w[1]), det(u[1], v[1], w[1])};
  const double bound[4] = {48 * kEps * p, 192 * kEps * p, 192 * kEps * p, 48 * kEps * p};
  int sign = 0;
  for (int i = 0; i < 4; ++i) {
    const int s = b[i] > bound[i] ? 1 : (-b[i] > bound[i] ? -1 : 0);
    if (s == 0 || (sign != 0 && s != sign)) return 0;
    sign = s;
  }
  return sign;
}

// ---- Stage 2: interval bisection on f and the inside conditions.

struct IVec {
  Interval x, y, z;
};
IVec operator-(const IVec& a, const IVec& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
IVec cross(const IVec& a, const IVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Interval dot(const IVec& a, const IVec& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

Interval lerp(double x0, double x1, const Interval& t) {
  const Interval a = Interval::point(x0);
  return a + t * (Interval::point(x1) - a);
}
IVec at(const Vec3& x0, const Vec3& x1, const Interval& t) {
  return {lerp(x0.x, x1.x, t), lerp(x0.y, x1.y, t), lerp(x0.z, x1.z, t)};
}

// f and the conditions g_i over a time interval. At a coplanar time, contact iff every
// g_i >= 0 (the same polynomials as reference/'s exact_ccd.cpp); g_i > 0 for all i implies
// contact, since the g_i all vanish when the triangle has zero area or the edges are parallel.
struct Conditions {
  Interval f, g[4];
  int n = 0;
};

Conditions vertex_face(const Query& q, const Interval& t) {
  const IVec p = at(q.x[0], q.x[4], t), a = at(q.x[1], q.x[5], t), b = at(q.x[2], q.x[6], t),
             c = at(q.x[3], q.x[7], t);
  const IVec ap = a - p, bp = b - p, cp = c - p, n = cross(b - a, c - a), bc = cross(bp, cp);
  // |n|^2 times p's barycentric coordinates when coplanar.
  return {dot(ap, bc), {dot(n, bc), dot(n, cross(cp, ap)), dot(n, cross(ap, bp))}, 3};
}

Conditions edge_edge(const Query& q, const Interval& t) {
  const IVec a0 = at(q.x[0], q.x[4], t), a1 = at(q.x[1], q.x[5], t), b0 = at(q.x[2], q.x[6], t),
             b1 = at(q.x[3], q.x[7], t);
  const IVec ea = a1 - a0, eb = b1 - b0, w = b0 - a0, m = cross(ea, eb);
  const Interval mm = dot(m, m), s = dot(cross(w, eb), m), u = dot(cross(w, ea), m);
  // a0 + (s/mm) ea = b0 + (u/mm) eb when coplanar: both parameters in [0, 1].
  return {dot(ea, cross(w, b1 - a0)), {s, mm - s, u, mm - u}, 4};
}

Filtered bisect(const Query& q) {
  const auto eval = q.kind == QueryKind::VertexFace ? &vertex_face : &edge_edge;
  constexpr int kMaxPieces = 16;   // evaluations before giving up
  Interval stack[kMaxPieces + 1];  // each piece pops one and pushes at most two
  int top = 0;
  stack[top++] = {0, 1};
  for (int pieces = 0; top > 0; ++pieces) {
    if (pieces == kMaxPieces) return Filtered::Uncertain;
    const Interval t = stack[--top];
    const Conditions c = eval(q, t);
    if (c.f.excludes_zero()) continue;
    bool outside = false, inside = true;
    for (int i = 0; i < c.n; ++i) outside |= c.g[i].negative(), inside &= c.g[i].positive();
    if (outside) continue;
    if (inside) {
      const Interval f0 = eval(q, Interval::point(t.lo)).f, f1 = eval(q, Interval::point(t.hi)).f;
      if ((f0.positive() && f1.negative()) || (f0.negative() && f1.positive()))
        return Filtered::Yes;
    }
    // Not the midpoint: handcrafted contacts sit at t = 1/2, 1/4, ..., and a piece that ends on
    // a root can never show f changing sign.
    const double mid = t.lo + 0.4914 * (t.hi - t.lo);
    stack[top++] = {mid, t.hi};
    stack[top++] = {t.lo, mid};
  }
  return Filtered::No;
}

}  // namespace

Filtered robust_ccd_filter(const Query& q) {
  // Interval bounds never overflow below 2^100: the conditions have degree 4 in coordinates.
  for (const Vec3& v : q.x)
    if (!(std::fabs(v.x) <= 0x1p100 && std::fabs(v.y) <= 0x1p100 && std::fabs(v.z) <= 0x1p100))
      return Filtered::Uncertain;
  // Both kinds: f = det(x1 - x0, x2 - x0, x3 - x0), at t = 0 and t = 1.
  const auto& x = q.x;
  const Vec3 u[2] = {x[1] - x[0], x[5] - x[4]}, v[2] = {x[2] - x[0], x[6] - x[4]},
             w[2] = {x[3] - x[0], x[7] - x[4]};
  if (bernstein_sign(u, v, w) != 0) return Filtered::No;
  return bisect(q);
}

}  // namespace fdh
