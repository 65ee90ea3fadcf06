// Self-collision culling by normal cones over a step (Volino & Magnenat-Thalmann 1994, "Efficient
// self-collision detection on smoothly discretized surface animations using geometrical shape
// regularity"): a surface patch cannot touch itself if, for some direction d,
//   1. every triangle's normal has d·n > 0 (the projection along d is then orientation
//      preserving on every triangle), and
//   2. its boundary, projected along d, is a simple closed curve.
// Then the projection is one-to-one on the patch (a degree argument: every point inside the
// projected boundary has as many preimages as the boundary's winding number around it, 1, each
// counted positively), so no two distinct points of the patch meet, and no two primitives that
// share no particle touch. For CCD, both must hold at every time of the step, with positions
// moving linearly as the CCD test moves them: here each is a quadratic in t checked through its
// Bernstein coefficients, and the boundary is checked as a contour star-shaped around a moving
// centre m (every boundary edge turns positively around m, and the contour winds once).
//
// Directions: the 13 of kDirections and their opposites, bit 2i for +d_i and 2i + 1 for -d_i.
// Everything is decided with a rounding-error bound, so a "yes" is certain; a "no" only costs
// the culling.
#pragma once

#include <cstdint>
#include <vector>

#include "fdh/vec3.hpp"

namespace fdh {

using DirectionMask = std::uint32_t;
inline constexpr DirectionMask kAllDirections = (1u << 26) - 1;

// The swept normals of a triangle, or of a union of triangles: a box holding the control
// normals of every n(t) = p(t) × q(t), t in [0, 1], with p(t) and q(t) moving linearly from p0
// to p1 and q0 to q1, each the rounded difference of two positions. n(t) is quadratic in t, so
// it is a positive combination of its three Bernstein control vectors (p0×q0,
// (p0×q1 + p1×q0)/2, p1×q1): d·n(t) > 0 for all t when d·c > 0 for every control vector c.
// lo and hi bound the computed control vectors, coordinate by coordinate; err bounds how far
// the true ones are from the computed ones, per coordinate. For a triangle abc, p = b - a and
// q = c - a.
struct NormalBox {
  Vec3 lo, hi;
  double err = 0;
};
NormalBox swept_normals(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);
NormalBox merge(const NormalBox& a, const NormalBox& b);

// The directions d (bits) with d·n > 0 certainly for every normal n held by the box.
DirectionMask positive_directions(const NormalBox& b);

// The direction of bit `bit` (0-25) as a vector.
Vec3 mask_direction(int bit);

// The set bit of `mask` whose direction is closest to `towards` (-1 if mask is empty).
int best_direction(DirectionMask mask, const Vec3& towards);

// Condition 2 for a closed contour of particles c[0], c[1], ..., c[n-1], c[0] (x0: at the start
// of the step, x1: at its end), around the moving centre m0 -> m1, for the direction of `bit`:
// every edge turns positively around m along d for the whole step, and the contour winds once.
bool contour_is_star_shaped(const std::vector<int>& contour, const std::vector<Vec3>& x0,
                            const std::vector<Vec3>& x1, const Vec3& m0, const Vec3& m1, int bit);

}  // namespace fdh
