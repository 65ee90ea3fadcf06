#include "fdh/normal_cone.hpp"

#include <cmath>
#include <limits>

#include "fdh/kdop.hpp"

namespace fdh {
using normal_cone_detail::kTiny;

// For d with coordinates in {-1, 0, 1}, the least d·n over the box is s = Σ (lo_i where
// d_i = 1, -hi_i where d_i = -1). The true control vectors are within err per coordinate, so
// their least d·n is at least s - 3·err; the float sum of three terms is within 2u·Σ|term| of
// s. So s > 3·err + 4u·Σ|term| (+ a margin for rounding that bound itself) is certain.
bool leans(const NormalBox& b, int bit) {
  const Direction& d = kDirections[bit / 2];
  const int sign = bit % 2 ? -1 : 1;
  const auto term = [&](int di, double lo, double hi) {
    const int e = sign * di;
    return e > 0 ? lo : e < 0 ? -hi : 0.0;
  };
  const double t0 = term(d.x, b.lo.x, b.hi.x), t1 = term(d.y, b.lo.y, b.hi.y),
               t2 = term(d.z, b.lo.z, b.hi.z);
  const double s = (t0 + t1) + t2;
  const double margin =
      1.01 * (3 * b.err + 4 * kEps * (std::fabs(t0) + std::fabs(t1) + std::fabs(t2))) + kTiny;
  return s > margin;
}

DirectionMask positive_directions(const NormalBox& b) {
  DirectionMask mask = 0;
  for (int bit = 0; bit < 26; ++bit)
    if (leans(b, bit)) mask |= 1u << bit;
  return mask;
}

Vec3 mask_direction(int bit) {
  const Direction& d = kDirections[bit / 2];
  const Vec3 v{double(d.x), double(d.y), double(d.z)};
  return bit % 2 ? -v : v;
}

int best_direction(DirectionMask mask, const Vec3& towards) {
  int best = -1;
  double best_score = -std::numeric_limits<double>::infinity();
  for (int bit = 0; bit < 26; ++bit) {
    if (!(mask >> bit & 1)) continue;
    const Vec3 d = mask_direction(bit);
    const double score = dot(d, towards) / norm(d);
    if (score > best_score) best = bit, best_score = score;
  }
  return best;
}

// In-plane axes u, w for the direction d (small integer vectors, exact), with (u × w)·d > 0:
// counter-clockwise seen from d.
static void plane_axes(const Vec3& d, Vec3& u, Vec3& w) {
  const Vec3 e = std::fabs(d.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};  // not parallel to d
  u = cross(d, e);
  w = cross(d, u);
  if (dot(cross(u, w), d) < 0) w = -w;
}

bool contour_is_star_shaped(const std::vector<int>& contour, const std::vector<Vec3>& x0,
                            const std::vector<Vec3>& x1, const Vec3& m0, const Vec3& m1, int bit) {
  const Vec3 d = mask_direction(bit);
  Vec3 u, w;
  plane_axes(d, u, w);
  // The quadrant of p around m in the plane (0-3, counter-clockwise), at the start of the step.
  const auto quadrant = [&](const Vec3& p) {
    const double a = dot(p, u), b = dot(p, w);
    return a > 0 ? (b >= 0 ? 0 : 3) : (b > 0 ? 1 : 2);
  };
  int advance = 0;  // quarter turns around m over the whole contour
  const std::size_t n = contour.size();
  for (std::size_t k = 0; k < n; ++k) {
    const int a = contour[k], b = contour[(k + 1) % n];
    const Vec3 p0 = x0[a] - m0, p1 = x1[a] - m1, q0 = x0[b] - m0, q1 = x1[b] - m1;
    // The edge turns positively around m along d for the whole step ...
    if (!leans(swept_normals(p0, p1, q0, q1), bit)) return false;
    // ... by less than a half turn, so its quadrant advance is 0, 1 or 2. A 3 can only come from
    // rounding at a quadrant's border: refused. Otherwise the advances add up to 4k for a
    // contour that winds k times (they telescope), and k is the same all step long (no edge
    // passes through m).
    const int step = (quadrant(q0) - quadrant(p0) + 4) % 4;
    if (step == 3) return false;
    advance += step;
  }
  return advance == 4;
}

}  // namespace fdh
