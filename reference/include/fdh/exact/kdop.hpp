// The exact twin of fdh::Kdop: the FDH of double points with every projection d·p computed
// exactly (GMP rationals), for checking that the float k-DOPs are conservative.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "fdh/kdop.hpp"
#include "fdh/vec3.hpp"

namespace fdh::exact {

// Slab s of a box has the integer direction dirs[s] and the extent [lo[s], hi[s]]: fdh::Kdop<k>'s
// slabs in its order, or another library's (verify/peers/).

// The first slab (0-based, in the order of dirs) where [lo, hi] fails to contain the exact
// extent of the points, or -1 when it contains them all.
int first_uncontained_slab(const std::vector<Direction>& dirs, const Vec3* pts, std::size_t n,
                           const double* lo, const double* hi);
// The same in fdh::Kdop<k> slab order.
int first_uncontained_slab(int k, const Vec3* pts, std::size_t n, const double* lo,
                           const double* hi);

// Whether the exact FDHs of the two point sets along dirs (or fdh::Kdop<k>'s) overlap (closed
// slabs).
bool kdops_overlap(const std::vector<Direction>& dirs, const Vec3* a, std::size_t na, const Vec3* b,
                   std::size_t nb);
bool kdops_overlap(int k, const Vec3* a, std::size_t na, const Vec3* b, std::size_t nb);

// The exact twin of tree traversal, by brute force: every pair (i, j) such that the exact
// k-DOPs of a[i] and b[j] overlap. Extents are computed once per set.
std::vector<std::pair<int, int>> overlapping_pairs(int k, const std::vector<std::vector<Vec3>>& a,
                                                   const std::vector<std::vector<Vec3>>& b);

}  // namespace fdh::exact
