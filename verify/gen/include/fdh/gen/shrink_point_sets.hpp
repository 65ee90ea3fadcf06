// Shrinking a failing bounding-volume case (one point set, or two): a greedy descent that keeps
// the failure while it removes points, moves every point toward the origin by a common dyadic
// translation, scales by powers of two, and makes coordinates zero or shorter (fewer significant
// bits). A step is taken only when it lowers the case's size (points first, then the bits and
// exponents of its coordinates), so the descent ends. Deterministic.
#pragma once

#include <functional>
#include <vector>

#include "fdh/vec3.hpp"

namespace fdh::verify {

using PointSets = std::vector<std::vector<Vec3>>;

// The case's size: 1000 per point, plus per nonzero coordinate its significant bits and the
// magnitude of its binary exponent.
long point_sets_size(const PointSets& sets);

// `sets` shrunk while fails(sets) holds, within max_evaluations calls of fails. Every set keeps
// at least one point. Precondition: fails(sets).
PointSets shrink_point_sets(PointSets sets, const std::function<bool(const PointSets&)>& fails,
                            int max_evaluations = 3000);

}  // namespace fdh::verify
