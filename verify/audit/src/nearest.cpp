#include "nearest.hpp"

#include <algorithm>
#include <cmath>

#include "fdh/exact/distance.hpp"

namespace fdh::audit {
namespace {

double clamp01(double t) {
  return std::min(1.0, std::max(0.0, t));
}

// Ericson, sec. 5.1.5: the closest point of triangle abc to p, by its Voronoi regions.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double sum = va + vb + vc;
  if (!(sum > 0)) return a;  // a degenerate triangle: its edges give the distance
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

// Ericson, sec. 5.1.9: the distance between segments p0p1 and q0q1.
double segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) return norm(r);
  if (a <= 0) {
    t = clamp01(f / e);
  } else {
    const double c = dot(d1, r);
    if (e <= 0) {
      s = clamp01(-c / a);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      s = denom > 0 ? clamp01((b * f - c * e) / denom) : 0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = clamp01(-c / a);
      if (t > 1) t = 1, s = clamp01((b - c) / a);
    }
  }
  return norm((p0 + s * d1) - (q0 + t * d2));
}

}  // namespace

double distance_estimate(const Triangle3& a, const Triangle3& b) {
  double d = HUGE_VAL;
  for (int i = 0; i < 3; ++i) {
    d = std::min(d, norm(a[i] - closest_on_triangle(a[i], b[0], b[1], b[2])));
    d = std::min(d, norm(b[i] - closest_on_triangle(b[i], a[0], a[1], a[2])));
    for (int j = 0; j < 3; ++j)
      d = std::min(d, segment_distance(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]));
  }
  return d;
}

Nearest nearest_of(const NearestCandidate& c, int frame, const Topology& t,
                   const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  Nearest n;
  if (c.a < 0) return n;
  n.kind = ViolationKind(c.kind);
  n.frame = frame;
  n.triangles = {c.a, c.b};
  const bool self = n.kind == ViolationKind::SelfProximity;
  const Tri& ta = t.cloth[std::size_t(c.a)];
  const Tri& tb = (self ? t.cloth : t.obstacle)[std::size_t(c.b)];
  const std::vector<Vec3>& yb = self ? x : y;
  const exact::TriangleDistance d =
      exact::triangle_distance({x[ta[0]], x[ta[1]], x[ta[2]]}, {yb[tb[0]], yb[tb[1]], yb[tb[2]]});
  n.squared = d.squared, n.lo = d.lo, n.hi = d.hi;
  return n;
}

}  // namespace fdh::audit
