// The "traditional method" of the paper's Table 1: solve B + t(B'-B) = D + u(E-D) + v(F-D)
// as a 3×3 system; hit iff t in [0,1], u >= 0, v >= 0, u + v <= 1. A singular system (motion in
// the plane, or no motion) answers "no", as the usual implementation does.
#pragma once

#include "fdh/vec3.hpp"

namespace fdh {

bool linear_system(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f);

}  // namespace fdh
