// The distance between a query's primitives at one time, against its minimum separation δ
// (q.min_distance), by CGAL's exact squared distances on rationals: a second formulation, with
// nothing in common with the separation search behind ccd_hit and ccd_toi (exact_separation.cpp)
// but the question, which the tests check that search against.
#pragma once

#include <array>
#include <string>

#include "fdh/query.hpp"

namespace fdh::exact {

// The sign of dist(t) - δ, exactly: the point and the closed triangle (vertex-face) or the two
// closed segments (edge-edge) at time t in [0, 1], each corner at x(0) + t (x(1) - x(0)) taken
// exactly; degenerate triangles and segments as the sets they are.
int compare_distance_at(const Query& q, double t);

// The distance between two closed triangles (zero-area ones as the points or segments they
// are), exactly: 0 where they meet, else the least of the 6 vertex-triangle and 9 edge-edge
// distances (the closest points of two disjoint triangles include a vertex of one, or lie on an
// edge of each: Ericson, Real-Time Collision Detection, 2005, sec. 5.1.11).
struct TriangleDistance {
  std::string squared;    // the squared distance, a rational "p/q" (or "p")
  double lo = 0, hi = 0;  // lo <= distance <= hi, doubles
};
TriangleDistance triangle_distance(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

// Whether the distance between the closed triangles is <= d (d >= 0 at the double's exact
// value): the squared distance compared exactly with d^2. The exact twin of the audit's
// within-a-frame proximity test (`fdhcert audit --min-distance`).
bool triangles_within(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b, double d);

}  // namespace fdh::exact
