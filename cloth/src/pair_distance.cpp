#include "fdh/cloth/pair_distance.hpp"

#include <algorithm>

namespace fdh::cloth {
namespace {

double clamp01(double x) {
  return std::clamp(x, 0.0, 1.0);
}

// Ericson §5.1.5: the Voronoi region of p; the closest point a + s (b - a) + u (c - a).
std::array<double, 2> point_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (d1 <= 0 && d2 <= 0) return {0, 0};
  if (d3 >= 0 && d4 <= d3) return {1, 0};
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return {d1 / (d1 - d3), 0};
  if (d6 >= 0 && d5 <= d6) return {0, 1};
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return {0, d2 / (d2 - d6)};
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double u = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {1 - u, u};
  }
  const double inv = 1 / (va + vb + vc);
  return {vb * inv, vc * inv};
}

// Ericson §5.1.9: p1 + s (q1 - p1) and p2 + t (q2 - p2), zero lengths included.
std::array<double, 2> segment_segment(const Vec3& p1, const Vec3& q1, const Vec3& p2,
                                      const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  if (a == 0 && e == 0) return {0, 0};
  if (a == 0) return {0, clamp01(f / e)};
  const double c = dot(d1, r);
  if (e == 0) return {clamp01(-c / a), 0};
  const double b = dot(d1, d2), denom = a * e - b * b;
  const double s = denom > 0 ? clamp01((b * f - c * e) / denom) : 0;
  const double t = (b * s + f) / e;
  if (t < 0) return {clamp01(-c / a), 0};
  if (t > 1) return {clamp01((b - c) / a), 1};
  return {s, t};
}

}  // namespace

PairClosest pair_closest(QueryKind kind, const std::array<Vec3, 4>& p) {
  PairClosest r;
  if (kind == QueryKind::VertexFace) {
    const auto [s, u] = point_triangle(p[0], p[1], p[2], p[3]);
    r.w = {1, 1 - s - u, s, u};
  } else {
    const auto [s, t] = segment_segment(p[0], p[1], p[2], p[3]);
    r.w = {1 - s, s, 1 - t, t};
  }
  const int split = kind == QueryKind::VertexFace ? 1 : 2;  // the second primitive's first point
  Vec3 a, b;
  for (int i = 0; i < 4; ++i) (i < split ? a : b) += r.w[i] * p[i];
  r.dir = a - b;
  r.distance = norm(r.dir);
  return r;
}

}  // namespace fdh::cloth
