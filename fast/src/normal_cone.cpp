#include "fdh/normal_cone.hpp"

#include <cmath>
#include <limits>

#include "fdh/kdop.hpp"

namespace fdh {
namespace {

constexpr double kU = 0x1p-53;  // unit roundoff
// Underflow: an absolute term far above the error of any product of subnormal size.
constexpr double kTiny = 1e-290;

double max_abs2(const Vec3& a, const Vec3& b) {
  const double x = max_abs(a), y = max_abs(b);
  return x > y ? x : y;
}

}  // namespace

// Error of each control vector's coordinates: the inputs carry a relative error u per
// coordinate; a cross-product coordinate a·b - c·e of inputs bounded by P and Q is then within
// (2u + u²)·2PQ (inputs) + 2u·PQ (products) + u·2PQ(1 + 4u) (difference) <= 8.1u·PQ; the middle
// vector's sum and halving keep it within 10.2u·PQ. 16u·PQ + kTiny is used.
NormalBox swept_normals(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 n0 = cross(p0, q0), n2 = cross(p1, q1);
  const Vec3 n1 = 0.5 * (cross(p0, q1) + cross(p1, q0));
  const auto lo = [](double a, double b, double c) {
    const double ab = a < b ? a : b;
    return ab < c ? ab : c;
  };
  const auto hi = [](double a, double b, double c) {
    const double ab = a > b ? a : b;
    return ab > c ? ab : c;
  };
  return {{lo(n0.x, n1.x, n2.x), lo(n0.y, n1.y, n2.y), lo(n0.z, n1.z, n2.z)},
          {hi(n0.x, n1.x, n2.x), hi(n0.y, n1.y, n2.y), hi(n0.z, n1.z, n2.z)},
          16 * kU * max_abs2(p0, p1) * max_abs2(q0, q1) + kTiny};
}

NormalBox merge(const NormalBox& a, const NormalBox& b) {
  const auto mn = [](double x, double y) { return x < y ? x : y; };
  const auto mx = [](double x, double y) { return x > y ? x : y; };
  return {{mn(a.lo.x, b.lo.x), mn(a.lo.y, b.lo.y), mn(a.lo.z, b.lo.z)},
          {mx(a.hi.x, b.hi.x), mx(a.hi.y, b.hi.y), mx(a.hi.z, b.hi.z)},
          mx(a.err, b.err)};
}

// For d with coordinates in {-1, 0, 1}, the least d·n over the box is s = Σ (lo_i where
// d_i = 1, -hi_i where d_i = -1). The true control vectors are within err per coordinate, so
// their least d·n is at least s - 3·err; the float sum of three terms is within 2u·Σ|term| of
// s. So s > 3·err + 4u·Σ|term| (+ a margin for rounding that bound itself) is certain.
DirectionMask positive_directions(const NormalBox& b) {
  DirectionMask mask = 0;
  for (int bit = 0; bit < 26; ++bit) {
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
        1.01 * (3 * b.err + 4 * kU * (std::fabs(t0) + std::fabs(t1) + std::fabs(t2))) + kTiny;
    if (s > margin) mask |= 1u << bit;
  }
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

bool contour_is_star_shaped(const std::vector<int>& contour, const std::vector<Vec3>& x0,
                            const std::vector<Vec3>& x1, const Vec3& m0, const Vec3& m1, int bit) {
  const DirectionMask want = 1u << bit;
  const Vec3 d = mask_direction(bit);
  const Vec3 du = (1 / norm(d)) * d;
  double turn = 0;  // the contour's total angle around m at the start, for its winding number
  const std::size_t n = contour.size();
  for (std::size_t k = 0; k < n; ++k) {
    const int a = contour[k], b = contour[(k + 1) % n];
    const Vec3 p0 = x0[a] - m0, p1 = x1[a] - m1, q0 = x0[b] - m0, q1 = x1[b] - m1;
    if (!(positive_directions(swept_normals(p0, p1, q0, q1)) & want)) return false;
    // Each edge turns by an angle in (0, π) around m (the test above), so the total is 2πk: a
    // float sum within π of 2π is k = 1 (each angle's rounding error is far below π / n).
    const double s = dot(du, cross(p0, q0));
    const double c = dot(p0, q0) - dot(p0, du) * dot(q0, du);
    turn += std::atan2(s, c);
  }
  return std::fabs(turn - 2 * M_PI) < M_PI;
}

}  // namespace fdh
