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

#include <algorithm>
#include <cstdint>
#include <vector>

#include "fdh/orient3d_filter.hpp"  // kEps, min_of, max_of
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

namespace normal_cone_detail {
// Underflow: an absolute term far above the error of any product of subnormal size.
inline constexpr double kTiny = 1e-290;
}  // namespace normal_cone_detail

// Error of each control vector's coordinates: the inputs carry a relative error u per
// coordinate; a cross-product coordinate a·b - c·e of inputs bounded by P and Q is then within
// (2u + u²)·2PQ (inputs) + 2u·PQ (products) + u·2PQ(1 + 4u) (difference) <= 8.1u·PQ; the middle
// vector's sum and halving keep it within 10.2u·PQ. 16u·PQ + kTiny is used. (Inline: the self
// pass calls it for every triangle of every step.)
inline NormalBox swept_normals(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  using namespace normal_cone_detail;
  const Vec3 n0 = cross(p0, q0), n2 = cross(p1, q1);
  const Vec3 n1 = 0.5 * (cross(p0, q1) + cross(p1, q0));
  const double pm = std::max(max_abs(p0), max_abs(p1)), qm = std::max(max_abs(q0), max_abs(q1));
  return {{min_of(n0.x, n1.x, n2.x), min_of(n0.y, n1.y, n2.y), min_of(n0.z, n1.z, n2.z)},
          {max_of(n0.x, n1.x, n2.x), max_of(n0.y, n1.y, n2.y), max_of(n0.z, n1.z, n2.z)},
          16 * kEps * pm * qm + kTiny};  // kEps: the unit roundoff u
}

inline NormalBox merge(const NormalBox& a, const NormalBox& b) {
  return {{min_of(a.lo.x, b.lo.x), min_of(a.lo.y, b.lo.y), min_of(a.lo.z, b.lo.z)},
          {max_of(a.hi.x, b.hi.x), max_of(a.hi.y, b.hi.y), max_of(a.hi.z, b.hi.z)},
          max_of(a.err, b.err)};
}

// The directions d (bits) with d·n > 0 certainly for every normal n held by the box; and
// whether the one of `bit` is.
DirectionMask positive_directions(const NormalBox& b);
bool leans(const NormalBox& b, int bit);

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
