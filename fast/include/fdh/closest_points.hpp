// The closest points of a point and a triangle, or of two segments, in plain floating point
// (Ericson, Real-Time Collision Detection, 2005): where to look, never a verdict by itself.
// robust's filters within δ (ccd_robust_delta.cpp) and the cloth's gap
// (fdh/cloth/pair_distance.hpp) use them. Inline: robust calls them in its inner loop.
#pragma once

#include "fdh/vec3.hpp"

namespace fdh {
namespace closest_detail {

inline double clamp01(double x) {
  return x < 0 ? 0 : (x > 1 ? 1 : x);  // NaN stays NaN: the rigorous test then fails
}

}  // namespace closest_detail

// The closest pair of two primitives, as parameters: vertex-face, the closest point of the
// triangle a + s (b - a) + u (c - a); edge-edge, a0 + s (a1 - a0) and b0 + u (b1 - b0). dir
// points from the second primitive's point to the first's (where they touch: the triangle's
// normal, or the lines' common normal); dist2 = |dir|² before that.
struct ClosestPoints {
  double s = 0, u = 0, dist2 = 0;
  Vec3 dir;
};

// Ericson, Real-Time Collision Detection (2005), 5.1.5: p's Voronoi region of the triangle.
inline ClosestPoints closest_point_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                            const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  ClosestPoints r;
  if (d1 <= 0 && d2 <= 0) {
    r.s = 0, r.u = 0;
  } else if (d3 >= 0 && d4 <= d3) {
    r.s = 1, r.u = 0;
  } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    r.s = d1 / (d1 - d3), r.u = 0;
  } else if (d6 >= 0 && d5 <= d6) {
    r.s = 0, r.u = 1;
  } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    r.s = 0, r.u = d2 / (d2 - d6);
  } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    r.u = (d4 - d3) / ((d4 - d3) + (d5 - d6)), r.s = 1 - r.u;
  } else {
    const double inv = 1 / (va + vb + vc);
    r.s = vb * inv, r.u = vc * inv;
  }
  r.dir = p - (a + r.s * ab + r.u * ac);
  r.dist2 = dot(r.dir, r.dir);
  if (!(r.dist2 > 0)) r.dir = cross(ab, ac);  // touching: the plane's normal
  return r;
}

// Ericson, 5.1.9: the closest points of two segments, zero lengths included.
inline ClosestPoints closest_segments(const Vec3& p1, const Vec3& q1, const Vec3& p2,
                                      const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, w = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, w);
  ClosestPoints r;
  if (a == 0) {
    r.u = e == 0 ? 0 : closest_detail::clamp01(f / e);
  } else {
    const double c = dot(d1, w);
    if (e == 0) {
      r.s = closest_detail::clamp01(-c / a);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      r.s = denom != 0 ? closest_detail::clamp01((b * f - c * e) / denom) : 0;
      r.u = (b * r.s + f) / e;
      if (r.u < 0) r.u = 0, r.s = closest_detail::clamp01(-c / a);
      if (r.u > 1) r.u = 1, r.s = closest_detail::clamp01((b - c) / a);
    }
  }
  r.dir = (p1 + r.s * d1) - (p2 + r.u * d2);
  r.dist2 = dot(r.dir, r.dir);
  if (!(r.dist2 > 0)) r.dir = cross(d1, d2);  // crossing: the lines' common normal
  return r;
}

}  // namespace fdh
