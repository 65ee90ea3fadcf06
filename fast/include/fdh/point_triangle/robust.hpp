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
// (multilinearity: the terms with q twice vanish), the sum of the other four. Two cross products
// serve all five: with a = q x d, q.(d x e) = a.e and q.(f x d) = -a.f (triple products rotate).
// Each is still a determinant of the rounded differences computed as 2 x 2 minors times a
// third vector's coordinates, the form Shewchuk's orient3d bound covers.
namespace point_triangle_detail {
// Two doubles side by side (GCC's and Clang's vector extension: SSE2 on x86-64, plain scalar
// code where there is no such unit). Lane by lane, each operation is the one IEEE operation of
// the scalar code, so the error bounds count the same roundings.
typedef double Pair __attribute__((vector_size(16)));
typedef long long PairBits __attribute__((vector_size(16)));
inline Pair pair_abs(Pair u) {
  return Pair(PairBits(u) & PairBits{0x7fffffffffffffffLL, 0x7fffffffffffffffLL});
}
inline Pair pair_max(Pair u, Pair w) {
  return u > w ? u : w;
}
inline double larger_lane(Pair u) {
  return max_of(u[0], u[1]);
}
inline Pair swapped(Pair u) {
  return Pair{u[1], u[0]};
}
// By coordinate, A = (e, q) and B = (f, d), apex P: A x B holds e x f and a = q x d.
struct Lanes {
  Pair ax, ay, az, bx, by, bz;
};
inline Lanes lanes(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f) {
  return {Pair{e.x, b1.x} - b0.x, Pair{e.y, b1.y} - b0.y, Pair{e.z, b1.z} - b0.z,
          Pair{f.x, d.x} - b0.x,  Pair{f.y, d.y} - b0.y,  Pair{f.z, d.z} - b0.z};
}
}  // namespace point_triangle_detail

// Stage 1, inline: one static bound for all five from the largest coordinates by axis. Its
// verdict as a code: 0 no, 1 yes, 2 uncertain, 3 uncertain with B or B' computed exactly in
// the plane (or out of range), where stage 2 would rarely be certain: a zero stays within any
// bound, and such queries are mostly true touches that the exact test settles at once.
inline int robust_point_triangle_stage1(const Vec3& b0, const Vec3& b1, const Vec3& d,
                                        const Vec3& e, const Vec3& f) {
  using namespace point_triangle_detail;
  // Two cross products side by side (Lanes). Half the instructions of the scalar code: the
  // loops that call this test are limited by how many instructions keep the next query's loads
  // waiting.
  const auto [ax, ay, az, bx, by, bz] = lanes(b0, b1, d, e, f);
  // The largest |coordinate| of d, e, f and q, by axis.
  const double mx = larger_lane(pair_max(pair_abs(ax), pair_abs(bx))),
               my = larger_lane(pair_max(pair_abs(ay), pair_abs(by))),
               mz = larger_lane(pair_max(pair_abs(az), pair_abs(bz)));
  const Pair kx = ay * bz - az * by, ky = az * bx - ax * bz, kz = ax * by - ay * bx;
  // (d, f) . (e x f, a) = (p, s3) and (q, e) . (e x f, a) = (-s2, -s1), lanes swapped from B, A.
  const Pair r1 = swapped(bx) * kx + swapped(by) * ky + swapped(bz) * kz;
  const Pair r2 = swapped(ax) * kx + swapped(ay) * ky + swapped(az) * kz;
  const double p = r1[0], s1 = -r2[1], s2 = -r2[0], s3 = r1[1];
  const double q = p + s1 + s2 + s3;
  // Each of the four is orient3d of rounded differences from the apex P, whose error
  // kOrient3dErrBound bounds (orient3d_filter.hpp), here with the maxima over all four vectors;
  // their sum's, kOrient3dSumErrBound.
  const double m = mx * my * mz, bound = kOrient3dErrBound * m, qbound = kOrient3dSumErrBound * m;
  // The bounds hold with every max in range (in_filter_range). A max of 0 makes every product
  // exactly 0, so nothing is certain then either: one range test of the smallest and largest.
  // A NaN coordinate, which the maxima may drop, makes p or one s_i NaN, hence q: q == q.
  const int valid = int(min_of(mx, my, mz) >= kFilterRangeMin) &
                    int(max_of(mx, my, mz) <= kFilterRangeMax) & int(q == q);
  // The signs as comparisons combined by & and |, not branches: on generic queries which exit
  // applies is a coin toss, and mispredicted branches cost more than the work they would skip.
  // fl(x - y) > 0 iff x > y, so min(p - bound, q - qbound) > 0 iff both certainly > 0.
  const int same_side =
      int(min_of(p - bound, q - qbound) > 0) | int(max_of(p + bound, q + qbound) < 0);
  const int both_certain = int(min_of(std::fabs(p) - bound, std::fabs(q) - qbound) > 0);
  const double smin = min_of(s1, s2, s3), smax = max_of(s1, s2, s3);
  const int line_misses = int(smax > bound) & int(smin < -bound);
  const int line_hits = int(smin > bound) | int(smax < -bound);
  // The code by arithmetic, not a branch; a yes (certainly opposite sides, all line signs
  // certainly equal) is never a no. A product that underflows to 0 only skips stage 2.
  const int no = same_side | line_misses, yes = both_certain & (1 - same_side) & line_hits;
  const int code = valid ? (1 - no) * (2 - yes) : 3;
  return code != 2 ? code : 2 + int(p * q == 0);  // a rare branch: no cost in the common case
}
static_assert(int(Filtered::No) == 0 && int(Filtered::Yes) == 1 && int(Filtered::Uncertain) == 2);

inline Filtered robust_point_triangle_quick(const Vec3& b0, const Vec3& b1, const Vec3& d,
                                            const Vec3& e, const Vec3& f) {
  const int code = robust_point_triangle_stage1(b0, b1, d, e, f);
  return Filtered(code < 2 ? code : 2);
}

// Stage 2, out of line, where stage 1 is uncertain: the same five determinants, each with its
// own bound from its permanent (Shewchuk's orient3d bound proper), tight where coordinates
// differ much in size, as in near contacts of long motions against small triangles
// (point_triangle_robust.cpp).
Filtered robust_point_triangle_tight(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                     const Vec3& f);

inline Filtered robust_point_triangle_filter(const Vec3& b0, const Vec3& b1, const Vec3& d,
                                             const Vec3& e, const Vec3& f) {
  const int code = robust_point_triangle_stage1(b0, b1, d, e, f);
  if (code < 2) return Filtered(code);
  return code == 2 ? robust_point_triangle_tight(b0, b1, d, e, f) : Filtered::Uncertain;
}

// A point–triangle test: does the point moving from b0 to b1 touch the still triangle def? The
// narrow phase of the cloth's simulation takes one.
using PointTriangleTest = bool (*)(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                   const Vec3& f);

// Stage 2 (if asked), then the exact test where it is uncertain too: one call that takes the
// arguments as they came (a tail call), so that the inline common case saves no registers for it.
bool robust_point_triangle_slow(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                const Vec3& f, PointTriangleTest exact_fallback, bool stage2);

inline bool robust_point_triangle(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                  const Vec3& f, PointTriangleTest exact_fallback) {
  const int code = robust_point_triangle_stage1(b0, b1, d, e, f);
  if (code < 2) return code == 1;
  return robust_point_triangle_slow(b0, b1, d, e, f, exact_fallback, code == 2);
}

}  // namespace fdh
