// `robust`: segment BB' against the closed still triangle DEF, decided by signs of orient3d
// behind a static error filter (fdh/orient3d_filter.hpp). The filter answers yes or no only
// when every sign it used is certain; otherwise the caller's exact test decides. So the
// verdict always equals the exact one. fast/ holds no exact arithmetic: the fallback is passed
// in (fdh::exact::point_triangle_hit from reference/ in this project). The filter is inline:
// its whole cost is a few dozen floating-point operations, and the call was a visible part.
#pragma once

#include "fdh/filtered.hpp"
#include "fdh/orient3d_filter.hpp"
#include "fdh/vec3.hpp"

namespace fdh {

// With P = B, Q = B' and the filtered signs (0 = uncertain):
// - P and Q certainly strictly on one side of the plane: no.
// - Line PQ meets the closed triangle iff the signs of orient3d(P,Q,D,E), (P,Q,E,F), (P,Q,F,D)
//   are all >= 0 or all <= 0. Two certain opposite signs: no. This holds for zero-area triangles
//   too: a line that meets the triangle makes all three signs zero there.
// - P and Q certainly on opposite sides and all three line signs certain (hence equal): yes.
//
// All five determinants from one apex, P: with d = D - P, e = E - P, f = F - P, q = Q - P (each
// one rounded difference),
//   orient3d(D,E,F,P) = d.(e x f),  orient3d(P,Q,D,E) = -q.(d x e)  (and cyclically),
//   orient3d(D,E,F,Q) = det(d - q, e - q, f - q) = d.(e x f) - q.(e x f + f x d + d x e)
// (multilinearity: the terms with q twice vanish), the sum of the other four. Three cross
// products serve all five instead of five separate orient3d evaluations.
inline Filtered robust_point_triangle_filter(const Vec3& b0, const Vec3& b1, const Vec3& d,
                                             const Vec3& e, const Vec3& f) {
  const Vec3 vd = d - b0, ve = e - b0, vf = f - b0, vq = b1 - b0;
  const double mx = max4(vd.x, ve.x, vf.x, vq.x), my = max4(vd.y, ve.y, vf.y, vq.y),
               mz = max4(vd.z, ve.z, vf.z, vq.z);
  if (!(in_filter_range(mx) && in_filter_range(my) && in_filter_range(mz)))
    return Filtered::Uncertain;
  const Vec3 ef = cross(ve, vf), fd = cross(vf, vd), de = cross(vd, ve);
  const double p = dot(vd, ef), s1 = -dot(vq, de), s2 = -dot(vq, ef), s3 = -dot(vq, fd);
  // Each of the four is orient3d of rounded differences from the apex P, whose error the
  // filter bounds (orient3d_filter.hpp), here with the maxima over all four vectors. Their sum
  // is off by at most four such bounds plus its three roundings, each at most eps times a sum
  // of terms below 6 (1 + eps)^3 maxx maxy maxz: 4 x 48 + 3 x 4 x 6 x 1.01 < 265; 272 allows it.
  const double m = mx * my * mz, bound = kOrient3dErrBound * m;
  const int sp = sign_beyond(p, bound), sq = sign_beyond(p + s1 + s2 + s3, 272 * kEps * m);
  if (sp != 0 && sp == sq) return Filtered::No;
  const int t1 = sign_beyond(s1, bound), t2 = sign_beyond(s2, bound), t3 = sign_beyond(s3, bound);
  const bool some_pos = t1 > 0 || t2 > 0 || t3 > 0;
  const bool some_neg = t1 < 0 || t2 < 0 || t3 < 0;
  if (some_pos && some_neg) return Filtered::No;
  if (sp != 0 && sq != 0 && t1 != 0 && t2 != 0 && t3 != 0) return Filtered::Yes;
  return Filtered::Uncertain;
}

using PointTriangleTest = bool (*)(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                   const Vec3& f);

inline bool robust_point_triangle(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                  const Vec3& f, PointTriangleTest exact_fallback) {
  return or_exact(robust_point_triangle_filter(b0, b1, d, e, f),
                  [&] { return exact_fallback(b0, b1, d, e, f); });
}

}  // namespace fdh
