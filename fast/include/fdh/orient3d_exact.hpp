// The exact sign of a signed volume of four double points, in floating point alone: error-free
// transformations summed into a nonoverlapping expansion (Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997, §2). For the rare
// queries where a filter meets a volume that may be exactly zero: the robust CCD filter asks it
// whether the motion is coplanar exactly at t = 0 or t = 1 (ccd_robust.cpp).
#pragma once

#include "fdh/vec3.hpp"

namespace fdh {

// The sign of det(p1 - p0, p2 - p0, p3 - p0) in `sign` (-1, 0 or 1), and true; false, with
// `sign` untouched, where this cannot vouch for it: a coordinate difference that is not an
// exact double, or a nonzero one outside [2^-300, 2^100] (products could then underflow or
// overflow).
bool exact_volume_sign(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, int& sign);

}  // namespace fdh
