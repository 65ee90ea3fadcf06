// `exact`: do two closed triangles meet? CGAL's exact do_intersect on exactly the given doubles;
// zero-area triangles (segments, points) are valid inputs, touching counts. The exact twin of
// fast/'s robust_triangles_intersect (fdh/triangle_triangle.hpp), and the fallback-free reference
// its property test compares with. (In exact_point_triangle.cpp: CGAL in few translation units.)
#pragma once

#include <array>

#include "fdh/vec3.hpp"

namespace fdh::exact {

bool triangles_intersect(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

}  // namespace fdh::exact
