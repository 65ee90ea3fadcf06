#include "fdh/cloth/pair_distance.hpp"

#include <algorithm>
#include <cmath>

namespace fdh::cloth {
namespace {

double clamp01(double x) {
  return std::clamp(x, 0.0, 1.0);
}

}  // namespace

// Ericson, Real-Time Collision Detection (2005), §5.1.5: the Voronoi region of p.
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  Vec3 q;
  if (d1 <= 0 && d2 <= 0) {
    q = a;
  } else if (d3 >= 0 && d4 <= d3) {
    q = b;
  } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    q = a + (d1 / (d1 - d3)) * ab;
  } else if (d6 >= 0 && d5 <= d6) {
    q = c;
  } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    q = a + (d2 / (d2 - d6)) * ac;
  } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    q = b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  } else {
    const double inv = 1 / (va + vb + vc);
    q = a + (vb * inv) * ab + (vc * inv) * ac;
  }
  return norm(p - q);
}

// Ericson, §5.1.9: the closest points of two segments.
double segment_segment_distance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a == 0 && e == 0) return norm(r);
  if (a == 0) {
    t = clamp01(f / e);
  } else {
    const double c = dot(d1, r);
    if (e == 0) {
      s = clamp01(-c / a);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      s = denom > 0 ? clamp01((b * f - c * e) / denom) : 0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0, s = clamp01(-c / a);
      } else if (t > 1) {
        t = 1, s = clamp01((b - c) / a);
      }
    }
  }
  return norm((p1 + s * d1) - (p2 + t * d2));
}

double pair_distance(QueryKind kind, const std::array<Vec3, 4>& p) {
  return kind == QueryKind::VertexFace ? point_triangle_distance(p[0], p[1], p[2], p[3])
                                       : segment_segment_distance(p[0], p[1], p[2], p[3]);
}

}  // namespace fdh::cloth
