// The distance of a query's primitives at a time, and its least over a span of the step, by brute
// force in long double, for the tests of `robust` within δ: by the closed sets' definitions, a
// point against a segment, a triangle (inside its plane's projection, else its three sides), two
// segments (the lines' closest pair when both parameters fall inside, else an end against the
// other segment). Degenerate triangles and zero-length segments come out as the sets they are.
#pragma once

#include <algorithm>
#include <cmath>

#include "fdh/query.hpp"

namespace fdh::brute {

using L = long double;
struct P {
  L x, y, z;
};
inline P operator-(P a, P b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline P operator+(P a, P b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline P operator*(L s, P a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline L dot(P a, P b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline P cross(P a, P b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline L clamp01(L x) {
  return std::clamp<L>(x, 0, 1);
}

inline L point_segment(P p, P a, P b) {
  const P e = b - a;
  const L ee = dot(e, e);
  const L s = ee > 0 ? clamp01(dot(p - a, e) / ee) : 0;
  const P d = p - (a + s * e);
  return std::sqrt(dot(d, d));
}
inline L point_triangle(P p, P a, P b, P c) {
  L best = std::min({point_segment(p, a, b), point_segment(p, b, c), point_segment(p, c, a)});
  const P n = cross(b - a, c - a);
  const L nn = dot(n, n);
  if (nn > 0 && dot(cross(b - a, p - a), n) >= 0 && dot(cross(c - b, p - b), n) >= 0 &&
      dot(cross(a - c, p - c), n) >= 0)
    best = std::min(best, std::fabs(dot(p - a, n)) / std::sqrt(nn));
  return best;
}
inline L segment_segment(P a0, P a1, P b0, P b1) {
  L best = std::min({point_segment(a0, b0, b1), point_segment(a1, b0, b1),
                     point_segment(b0, a0, a1), point_segment(b1, a0, a1)});
  const P ea = a1 - a0, eb = b1 - b0, w = a0 - b0;
  const L a = dot(ea, ea), b = dot(ea, eb), e = dot(eb, eb), d = dot(ea, w), f = dot(eb, w);
  const L den = a * e - b * b;
  if (den > 0) {
    const L s = (b * f - d * e) / den, u = (a * f - b * d) / den;
    if (s >= 0 && s <= 1 && u >= 0 && u <= 1) {
      const P g = (a0 + s * ea) - (b0 + u * eb);
      best = std::min(best, std::sqrt(dot(g, g)));
    }
  }
  return best;
}

inline L distance_at(const Query& q, L t) {
  P x[4];
  for (int i = 0; i < 4; ++i) {
    const Vec3 &u = q.x[i], &v = q.x[i + 4];
    x[i] = {u.x + t * (v.x - u.x), u.y + t * (v.y - u.y), u.z + t * (v.z - u.z)};
  }
  return q.kind == QueryKind::VertexFace ? point_triangle(x[0], x[1], x[2], x[3])
                                         : segment_segment(x[0], x[1], x[2], x[3]);
}

// The least distance over [0, t_end]: 4096 samples, then a golden-section refinement around
// the least.
inline L least_distance(const Query& q, L t_end) {
  constexpr int n = 4096;
  int best = 0;
  L dmin = distance_at(q, 0);
  for (int i = 1; i <= n; ++i) {
    const L d = distance_at(q, t_end * i / n);
    if (d < dmin) dmin = d, best = i;
  }
  L lo = t_end * std::max(0, best - 1) / n, hi = t_end * std::min(n, best + 1) / n;
  const L g = (std::sqrt(L(5)) - 1) / 2;
  for (int it = 0; it < 100; ++it) {
    const L m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    const L d1 = distance_at(q, m1), d2 = distance_at(q, m2);
    dmin = std::min({dmin, d1, d2});
    (d1 < d2 ? hi : lo) = d1 < d2 ? m2 : m1;
  }
  return dmin;
}

}  // namespace fdh::brute
