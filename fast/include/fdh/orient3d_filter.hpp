// A static floating-point filter for the sign of orient3d(a,b,c,d) = det[a-d; b-d; c-d]: its
// error bound, and the sign it certifies (+1 or -1) only when certain, 0 ("uncertain")
// otherwise: a true zero is never certified, so callers fall back to exact arithmetic for
// touching cases. The static point-triangle filter (point_triangle/robust.hpp) evaluates its
// five from one apex with these bounds; the CCD filter (ccd_robust.cpp) uses them for its
// Bernstein coefficients. One derivation, here; the callers name the constants.
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

// A sum of four such determinants, all bounded with one maxx maxy maxz = m, added in three
// roundings: four bounds, plus three roundings of partial sums of at most four terms, each
// term below 6.01 m: 4 x 48 + 3 x 4 x 6.01 = 264.2, < 272 with m's own two roundings. The
// static point-triangle filter's orient3d at the segment's far end (point_triangle/robust.hpp).
inline constexpr double kOrient3dSumErrBound = 4 * kOrient3dErrBound + 80 * kEps;

// The mean of three such determinants, (a + b + c) / 3, as the CCD filter's inner Bernstein
// coefficients are (ccd_robust.cpp): the sum is off by 3 x 48 plus two roundings of at most
// 3 x 6.01 = 18.03 (times eps m) each, so its third by (144 + 36.1) / 3 = 60.1, plus the
// division's rounding, eps x 6.01 m: 66.1 < 72 with m's two roundings.
inline constexpr double kOrient3dMeanOfThreeErrBound = kOrient3dErrBound + 24 * kEps;

// The bound assumes no overflow and no underflow of consequence. With every max in
// [2^-300, 2^300] (or 0), products stay finite, and an underflowed product (absolute error
// <= 2^-1075) is scaled by at most one max, which is < 2^-470 of maxx maxy maxz: negligible.
inline constexpr double kFilterRangeMin = 0x1p-300, kFilterRangeMax = 0x1p300;
inline bool in_filter_range(double m) {
  return m == 0 || (m >= kFilterRangeMin && m <= kFilterRangeMax);
}

// Smallest and largest (minsd and maxsd; plain comparisons, not std::fmin and std::fmax, which
// must order NaNs and are not one instruction).
inline double min_of(double a, double b) {
  return a < b ? a : b;
}
inline double max_of(double a, double b) {
  return a > b ? a : b;
}
inline double min_of(double a, double b, double c) {
  return min_of(min_of(a, b), c);
}
inline double max_of(double a, double b, double c) {
  return max_of(max_of(a, b), c);
}

// The sign of a computed value whose error is below `bound`; 0 (uncertain) when |x| <= bound.
// A NaN is uncertain too.
inline int sign_beyond(double x, double bound) {
  return x > bound ? 1 : (-x > bound ? -1 : 0);
}

}  // namespace fdh
