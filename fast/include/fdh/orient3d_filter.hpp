// A static floating-point filter for the sign of orient3d(a,b,c,d) = det[a-d; b-d; c-d]: its
// error bound, and the sign it certifies (+1 or -1) only when certain, 0 ("uncertain")
// otherwise: a true zero is never certified, so callers fall back to exact arithmetic for
// touching cases. The static point-triangle filter (point_triangle/robust.hpp) evaluates its
// five from one apex with this bound; the CCD filter (ccd_robust.cpp) uses the bound for its
// determinants at t = 0 and 1.
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
inline double max4(double a, double b, double c, double d) {
  const double abc = max3(a, b, c);
  d = std::fabs(d);
  return abc > d ? abc : d;
}

// The sign of a computed value whose error is below `bound`; 0 (uncertain) when |x| <= bound.
// A NaN is uncertain too.
inline int sign_beyond(double x, double bound) {
  return x > bound ? 1 : (-x > bound ? -1 : 0);
}

}  // namespace fdh
