// The exact twin of fdh::Kdop: the FDH of double points with every projection d·p computed
// exactly (GMP rationals), for checking that the float k-DOPs are conservative.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "fdh/vec3.hpp"

namespace fdh::exact {

// The first slab (0-based, in fdh::Kdop<k> order) where [lo, hi] fails to contain the exact
// extent of the points, or -1 when it contains them all.
int first_uncontained_slab(int k, const Vec3* pts, std::size_t n, const double* lo,
                           const double* hi);

// Whether the exact k-DOPs of the two point sets overlap (closed slabs).
bool kdops_overlap(int k, const Vec3* a, std::size_t na, const Vec3* b, std::size_t nb);

// The exact twin of tree traversal, by brute force: every pair (i, j) such that the exact
// k-DOPs of a[i] and b[j] overlap. Extents are computed once per set.
std::vector<std::pair<int, int>> overlapping_pairs(int k, const std::vector<std::vector<Vec3>>& a,
                                                   const std::vector<std::vector<Vec3>>& b);

}  // namespace fdh::exact
