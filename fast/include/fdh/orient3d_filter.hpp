// A static floating-point filter for the sign of orient3d(a,b,c,d) = det[a-d; b-d; c-d].
// It answers +1 or -1 only when the sign is certain, and 0 ("uncertain") otherwise: a true
// zero is never certified, so callers fall back to exact arithmetic for touching cases.
#pragma once

#include <cmath>

#include "fdh/vec3.hpp"

namespace fdh {

// Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
// Discrete Comput. Geom. 18 (1997), §4.3: with eps = 2^-53, the error of the floating-point
// orient3d, differences included, is below (7 + 56 eps) eps × permanent. The bound assumes no
// underflow or overflow; see in_filter_range().
inline constexpr double kEps = 0x1p-53;
inline constexpr double kOrient3dErrBound = (7.0 + 56.0 * kEps) * kEps;

// Differences whose magnitudes lie in [2^-300, 2^300] (or are 0) keep every product of three
// of them in the normal range, so the bound above holds. Outside it, the filter says uncertain.
inline bool in_filter_range(double v) {
  const double a = std::fabs(v);
  return a == 0 || (a >= 0x1p-300 && a <= 0x1p300);
}

inline int orient3d_filtered(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  if (!(in_filter_range(adx) && in_filter_range(ady) && in_filter_range(adz) &&
        in_filter_range(bdx) && in_filter_range(bdy) && in_filter_range(bdz) &&
        in_filter_range(cdx) && in_filter_range(cdy) && in_filter_range(cdz)))
    return 0;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  const double bound = kOrient3dErrBound * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 0;
}

}  // namespace fdh
