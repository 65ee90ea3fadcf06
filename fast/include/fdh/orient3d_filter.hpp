// A static floating-point filter for the sign of orient3d(a,b,c,d) = det[a-d; b-d; c-d].
// It answers +1 or -1 only when the sign is certain, and 0 ("uncertain") otherwise: a true
// zero is never certified, so callers fall back to exact arithmetic for touching cases.
#pragma once

#include <cmath>

#include "fdh/vec3.hpp"

namespace fdh {

// Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
// Discrete Comput. Geom. 18 (1997), §4.3: with eps = 2^-53, the error of the floating-point
// orient3d, differences included, is below (7 + 56 eps) eps × permanent, where
// permanent = Σ (|bdx cdy| + |cdx bdy|) |adz| + ... <= 6 (1 + eps)^3 maxx maxy maxz, with maxx the
// largest |x difference| and so on. So 48 eps × fl(maxx maxy maxz) bounds the error: 42 eps and
// change, plus the two roundings of the product. (A semi-static filter in the sense of Meyer and
// Pion, "FPG", 2008: a handful of operations instead of the permanent.)
inline constexpr double kEps = 0x1p-53;
inline constexpr double kOrient3dErrBound = 48 * kEps;

// The bound assumes no overflow and no underflow of consequence. With every max in
// [2^-300, 2^300] (or 0), products stay finite, and an underflowed product (absolute error
// <= 2^-1075) is scaled by at most one max, which is < 2^-470 of maxx maxy maxz: negligible.
inline bool in_filter_range(double m) {
  return m == 0 || (m >= 0x1p-300 && m <= 0x1p300);
}

// Plain comparisons (not std::fmax, which must order NaNs and is not one instruction).
inline double max3(double a, double b, double c) {
  a = std::fabs(a), b = std::fabs(b), c = std::fabs(c);
  const double ab = a > b ? a : b;
  return ab > c ? ab : c;
}

inline int orient3d_filtered(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  const double mx = max3(adx, bdx, cdx), my = max3(ady, bdy, cdy), mz = max3(adz, bdz, cdz);
  if (!(in_filter_range(mx) && in_filter_range(my) && in_filter_range(mz))) return 0;
  const double det =
      adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) + cdz * (adx * bdy - bdx * ady);
  // A zero max makes every term, hence det, exactly 0: uncertain, as it must be.
  const double bound = kOrient3dErrBound * (mx * my * mz);
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 0;
}

}  // namespace fdh
