#include "fdh/point_triangle/robust.hpp"

#include "fdh/orient3d_filter.hpp"

namespace fdh {

// With P = B, Q = B' and the filtered signs (0 = uncertain):
// - P and Q certainly strictly on one side of the plane: no.
// - Line PQ meets the closed triangle iff the signs of orient3d(P,Q,D,E), (P,Q,E,F), (P,Q,F,D)
//   are all >= 0 or all <= 0. Two certain opposite signs: no. This holds for zero-area triangles
//   too: a line that meets the triangle makes all three signs zero there.
// - P and Q certainly on opposite sides and all three line signs certain (hence equal): yes.
Filtered robust_point_triangle_filter(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                      const Vec3& f) {
  const int sp = orient3d_filtered(d, e, f, b0);
  const int sq = orient3d_filtered(d, e, f, b1);
  if (sp != 0 && sp == sq) return Filtered::No;
  const int s1 = orient3d_filtered(b0, b1, d, e);
  const int s2 = orient3d_filtered(b0, b1, e, f);
  const int s3 = orient3d_filtered(b0, b1, f, d);
  const bool some_pos = s1 > 0 || s2 > 0 || s3 > 0;
  const bool some_neg = s1 < 0 || s2 < 0 || s3 < 0;
  if (some_pos && some_neg) return Filtered::No;
  if (sp != 0 && sq != 0 && s1 != 0 && s2 != 0 && s3 != 0) return Filtered::Yes;
  return Filtered::Uncertain;
}

}  // namespace fdh
