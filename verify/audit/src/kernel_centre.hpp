// A centre for the contour test of normal_cone.hpp (contour_is_star_shaped): a point inside the
// kernel of the contour projected along a direction, where one exists. The test passes only
// when the centre sees every boundary edge turning positively, i.e. lies in the kernel (the
// intersection of the edges' inner half-planes); the loop's mean often does not, on the
// staircase-shaped patches a spatial tree makes of a grid. The test is sound for any centre, so
// this is a heuristic choice and nothing more.
#pragma once

#include <vector>

#include "fdh/vec3.hpp"

namespace fdh::audit {

// The mean of the kernel's corners (found by clipping the loop's bounding square by each edge's
// inner half-plane, the loop counter-clockwise seen from the direction of `bit`), lifted into
// 3D beside the loop's mean; the loop's mean itself when the kernel is empty.
Vec3 kernel_centre(const std::vector<int>& loop, const std::vector<Vec3>& x, int bit);

}  // namespace fdh::audit
