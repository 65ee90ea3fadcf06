// The distance between two of the cloth's primitives at one instant, in plain floating point:
// a vertex and a triangle, or two edges. The self-collision pass uses it to see which pairs
// already lie within the gap at the start of a step, and to report the smallest distance kept;
// neither decides a contact (robust CCD does, fdh/ccd/robust.hpp), so rounding here costs at
// most a stop earlier or later, never a crossing.
#pragma once

#include <array>

#include "fdh/query.hpp"
#include "fdh/vec3.hpp"

namespace fdh::cloth {

// |p - closest point of the triangle abc|.
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// The distance between the segments p1 q1 and p2 q2 (zero lengths allowed).
double segment_segment_distance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2);

// A query's four points at one instant: vertex–face (v, f0, f1, f2) or edge–edge (a0, a1, b0, b1).
double pair_distance(QueryKind kind, const std::array<Vec3, 4>& p);

}  // namespace fdh::cloth
