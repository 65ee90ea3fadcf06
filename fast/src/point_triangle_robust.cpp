#include <cmath>

#include "fdh/orient3d_filter.hpp"
#include "fdh/point_triangle/robust.hpp"

namespace fdh {
namespace {

using namespace point_triangle_detail;

// Shewchuk 1997, §4.3: u.(v x w), computed as the sum over axes of u's coordinate times a 2 x 2
// minor of v and w (each coordinate one rounded difference), is off by at most
// (7 + 56 eps) eps times its permanent, the same sum with every product and minor replaced by
// absolute values. The permanent computed here is itself rounded, low by a factor of at most
// (1 + eps)^4: 9 eps times it covers both. Products below the normal range lose up to 2^-1075
// each, scaled by at most a coordinate (<= 2^300 here): 2^-768 covers the six of a determinant.
Pair error_bounds(Pair permanents) {
  return 9 * kEps * permanents + 0x1p-768;
}

}  // namespace

// The determinants of stage 1 (robust.hpp), the same lanes and operations, each now with the
// bound of its own permanent. Lane by lane: r1 = (p, s3), r2 = (-s2, -s1).
Filtered robust_point_triangle_tight(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                     const Vec3& f) {
  const auto [ax, ay, az, bx, by, bz] = lanes(b0, b1, d, e, f);
  const double largest = max_of(larger_lane(pair_max(pair_abs(ax), pair_abs(bx))),
                                larger_lane(pair_max(pair_abs(ay), pair_abs(by))),
                                larger_lane(pair_max(pair_abs(az), pair_abs(bz))));
  const Pair yz = ay * bz, zy = az * by, zx = az * bx, xz = ax * bz, xy = ax * by, yx = ay * bx;
  const Pair kx = yz - zy, ky = zx - xz, kz = xy - yx;
  const Pair r1 = swapped(bx) * kx + swapped(by) * ky + swapped(bz) * kz;
  const Pair r2 = swapped(ax) * kx + swapped(ay) * ky + swapped(az) * kz;
  const Pair mx = pair_abs(yz) + pair_abs(zy), my = pair_abs(zx) + pair_abs(xz),
             mz = pair_abs(xy) + pair_abs(yx);
  const Pair e1 = error_bounds(pair_abs(swapped(bx)) * mx + pair_abs(swapped(by)) * my +
                               pair_abs(swapped(bz)) * mz),
             e2 = error_bounds(pair_abs(swapped(ax)) * mx + pair_abs(swapped(ay)) * my +
                               pair_abs(swapped(az)) * mz);
  const double p = r1[0], s1 = -r2[1], s2 = -r2[0], s3 = r1[1], q = p + s1 + s2 + s3;
  // A NaN coordinate, which the maxima may drop, makes q NaN (stage 1).
  if (!(largest <= kFilterRangeMax) || !(q == q)) return Filtered::Uncertain;
  // q: the four errors, plus its three additions, each off by at most eps times a partial sum
  // below T = |p| + |s1| + |s2| + |s3| (times (1 + eps)^3): 3.0001 eps T. The factor
  // 1 + 2^-48 covers the roundings of these sums themselves.
  const double t = std::fabs(p) + std::fabs(s1) + std::fabs(s2) + std::fabs(s3);
  const double eq = (e1[0] + e1[1] + e2[0] + e2[1] + 4 * kEps * t) * (1 + 0x1p-48);
  const int sp = sign_beyond(p, e1[0]), sq = sign_beyond(q, eq);
  const int t1 = sign_beyond(s1, e2[1]), t2 = sign_beyond(s2, e2[0]), t3 = sign_beyond(s3, e1[1]);
  // The verdict as in stage 1: same side, or a line sign against another: no; opposite sides
  // and three equal line signs: yes.
  if (sp != 0 && sp == sq) return Filtered::No;
  if ((t1 > 0 || t2 > 0 || t3 > 0) && (t1 < 0 || t2 < 0 || t3 < 0)) return Filtered::No;
  if (sp != 0 && sq != 0 && t1 != 0 && t2 != 0 && t3 != 0) return Filtered::Yes;
  return Filtered::Uncertain;
}

bool robust_point_triangle_slow(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                const Vec3& f, PointTriangleTest exact_fallback, bool stage2) {
  return or_exact(stage2 ? robust_point_triangle_tight(b0, b1, d, e, f) : Filtered::Uncertain,
                  [&] { return exact_fallback(b0, b1, d, e, f); });
}

}  // namespace fdh
