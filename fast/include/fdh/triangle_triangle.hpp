// `robust` static triangle-triangle intersection of two closed triangles, built from the
// segment-triangle decision `robust` (fdh/point_triangle/robust.hpp) and its exact fallback,
// passed in (fdh::exact::point_triangle_hit in this project); the exact twin is
// fdh::exact::triangles_intersect (reference/, CGAL). The audit's frame check (verify/audit/).
//
// Two closed triangles A and B meet iff one of the six edges (three of each) meets the other
// closed triangle. If an edge point lies in the other triangle they meet. Conversely take p in
// both. If p is on an edge of A or B, done. Otherwise move p along a direction d inside both
// planes: the line where they cross, or any direction in the plane when they are coplanar. Both
// triangles are bounded, so moving along d the point leaves one of them first, and the point
// where it leaves is still in both (closed sets) and on that triangle's boundary: an edge. A
// zero-area triangle is the union of its edges (a segment or a point), so it is covered too; so
// are coplanar, touching and shared-plane pairs, with no case of their own.
#pragma once

#include <array>

#include "fdh/point_triangle/robust.hpp"
#include "fdh/vec3.hpp"

namespace fdh {

using Triangle3 = std::array<Vec3, 3>;

// The first of the six edges that meets the other closed triangle, or -1 when the triangles do
// not meet: 0-2 are A's edges a0a1, a1a2, a2a0 against B, 3-5 B's edges b0b1, b1b2, b2b0
// against A. Exact: the verdict always equals the exact one (each edge's `robust` decision
// falls back to exact_fallback where its filter is uncertain). Cheap early outs first: the
// triangles' axis-aligned boxes apart (exact comparisons), then all of one triangle's corners
// certainly strictly on one side of the other's plane (the filtered orient3d of
// orient3d_filter.hpp): the common case costs a few orient3ds.
int robust_triangle_triangle_edge(const Triangle3& a, const Triangle3& b,
                                  PointTriangleTest exact_fallback);

inline bool robust_triangles_intersect(const Triangle3& a, const Triangle3& b,
                                       PointTriangleTest exact_fallback) {
  return robust_triangle_triangle_edge(a, b, exact_fallback) >= 0;
}

// The sign of orient3d(a, b, c, p) = det[a - p; b - p; c - p] where the static filter certifies
// it (+1 or -1), else 0 (uncertain; a true zero is never certified).
int filtered_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p);

}  // namespace fdh
