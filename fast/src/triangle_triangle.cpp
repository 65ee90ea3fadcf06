#include "fdh/triangle_triangle.hpp"

#include <cmath>

#include "fdh/orient3d_filter.hpp"

namespace fdh {

int filtered_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  const Vec3 u = a - p, v = b - p, w = c - p;  // rounded differences: the bound counts them
  const double det = dot(u, cross(v, w));
  const double mx = max_of(std::fabs(u.x), std::fabs(v.x), std::fabs(w.x));
  const double my = max_of(std::fabs(u.y), std::fabs(v.y), std::fabs(w.y));
  const double mz = max_of(std::fabs(u.z), std::fabs(v.z), std::fabs(w.z));
  if (!in_filter_range(mx) || !in_filter_range(my) || !in_filter_range(mz)) return 0;
  return sign_beyond(det, kOrient3dErrBound * (mx * my * mz));  // orient3d_filter.hpp's bound
}

namespace {

// The boxes are apart on some axis: exact comparisons of the coordinates themselves.
bool boxes_apart(const Triangle3& a, const Triangle3& b) {
  const auto apart = [&](double Vec3::*c) {
    const double alo = min_of(a[0].*c, a[1].*c, a[2].*c), ahi = max_of(a[0].*c, a[1].*c, a[2].*c);
    const double blo = min_of(b[0].*c, b[1].*c, b[2].*c), bhi = max_of(b[0].*c, b[1].*c, b[2].*c);
    return ahi < blo || bhi < alo;
  };
  return apart(&Vec3::x) || apart(&Vec3::y) || apart(&Vec3::z);
}

// Every corner of `p` certainly strictly on one side of the plane of `t`.
bool strictly_one_side(const Triangle3& t, const Triangle3& p) {
  const int s0 = filtered_orient3d(t[0], t[1], t[2], p[0]);
  if (s0 == 0) return false;
  return filtered_orient3d(t[0], t[1], t[2], p[1]) == s0 &&
         filtered_orient3d(t[0], t[1], t[2], p[2]) == s0;
}

}  // namespace

int robust_triangle_triangle_edge(const Triangle3& a, const Triangle3& b,
                                  PointTriangleTest exact_fallback) {
  if (boxes_apart(a, b) || strictly_one_side(a, b) || strictly_one_side(b, a)) return -1;
  for (int e = 0; e < 3; ++e)
    if (robust_point_triangle(a[e], a[(e + 1) % 3], b[0], b[1], b[2], exact_fallback)) return e;
  for (int e = 0; e < 3; ++e)
    if (robust_point_triangle(b[e], b[(e + 1) % 3], a[0], a[1], a[2], exact_fallback)) return 3 + e;
  return -1;
}

}  // namespace fdh
