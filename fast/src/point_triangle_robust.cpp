#include <cmath>

#include "fdh/orient3d_filter.hpp"
#include "fdh/point_triangle/robust.hpp"

namespace fdh {
namespace {

// Shewchuk 1997, §4.3: u.(v x w), computed as the sum over axes of u's coordinate times a 2 x 2
// minor of v and w (each coordinate one rounded difference), is off by at most
// (7 + 56 eps) eps times its permanent, the same sum with every product and minor replaced by
// absolute values. The permanent computed here is itself rounded, low by a factor of at most
// (1 + eps)^4: 9 eps times it covers both. Products below the normal range lose up to 2^-1075
// each, scaled by at most a coordinate (<= 2^300 here): 2^-768 covers the six of a determinant.
double error_bound(const Vec3& u, const Vec3& v, const Vec3& w) {
  using std::fabs;
  const double permanent = fabs(u.x) * (fabs(v.y * w.z) + fabs(v.z * w.y)) +
                           fabs(u.y) * (fabs(v.z * w.x) + fabs(v.x * w.z)) +
                           fabs(u.z) * (fabs(v.x * w.y) + fabs(v.y * w.x));
  return 9 * kEps * permanent + 0x1p-768;
}

bool in_range(const Vec3& v) {
  return std::fabs(v.x) <= kFilterRangeMax && std::fabs(v.y) <= kFilterRangeMax &&
         std::fabs(v.z) <= kFilterRangeMax;  // false for a NaN
}

}  // namespace

// The determinants of stage 1 (robust.hpp), in the same order of operations, scalar.
Filtered robust_point_triangle_tight(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                     const Vec3& f) {
  const Vec3 vd = d - b0, ve = e - b0, vf = f - b0, vq = b1 - b0;
  if (!(in_range(vd) && in_range(ve) && in_range(vf) && in_range(vq))) return Filtered::Uncertain;
  const Vec3 ef = cross(ve, vf), a = cross(vq, vd);
  const double p = dot(vd, ef), s1 = -dot(a, ve), s2 = -dot(vq, ef), s3 = dot(a, vf);
  const double q = p + s1 + s2 + s3;
  const double ep = error_bound(vd, ve, vf), e1 = error_bound(ve, vq, vd),
               e2 = error_bound(vq, ve, vf), e3 = error_bound(vf, vq, vd);
  // q: the four errors, plus its three additions, each off by at most eps times a partial sum
  // below T = |p| + |s1| + |s2| + |s3| (times (1 + eps)^3): 3.0001 eps T. The factor
  // 1 + 2^-48 covers the roundings of these sums themselves.
  const double t = std::fabs(p) + std::fabs(s1) + std::fabs(s2) + std::fabs(s3);
  const double eq = (ep + e1 + e2 + e3 + 4 * kEps * t) * (1 + 0x1p-48);
  const int sp = sign_beyond(p, ep), sq = sign_beyond(q, eq);
  const int t1 = sign_beyond(s1, e1), t2 = sign_beyond(s2, e2), t3 = sign_beyond(s3, e3);
  // The verdict as in stage 1 (robust.hpp): same side, or a line sign against another: no;
  // opposite sides and three equal line signs: yes.
  if (sp != 0 && sp == sq) return Filtered::No;
  if ((t1 > 0 || t2 > 0 || t3 > 0) && (t1 < 0 || t2 < 0 || t3 < 0)) return Filtered::No;
  if (sp != 0 && sq != 0 && t1 != 0 && t2 != 0 && t3 != 0) return Filtered::Yes;
  return Filtered::Uncertain;
}

bool robust_point_triangle_slow(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                const Vec3& f, PointTriangleTest exact_fallback) {
  return or_exact(robust_point_triangle_tight(b0, b1, d, e, f),
                  [&] { return exact_fallback(b0, b1, d, e, f); });
}

}  // namespace fdh
