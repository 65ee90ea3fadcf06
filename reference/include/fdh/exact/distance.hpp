// The distance between a query's primitives at one time, against its minimum separation δ
// (q.min_distance), by CGAL's exact squared distances on rationals: a second formulation, with
// nothing in common with the separation search behind ccd_hit and ccd_toi (exact_separation.cpp)
// but the question, which the tests check that search against.
#pragma once

#include "fdh/query.hpp"

namespace fdh::exact {

// The sign of dist(t) - δ, exactly: the point and the closed triangle (vertex-face) or the two
// closed segments (edge-edge) at time t in [0, 1], each corner at x(0) + t (x(1) - x(0)) taken
// exactly; degenerate triangles and segments as the sets they are.
int compare_distance_at(const Query& q, double t);

}  // namespace fdh::exact
