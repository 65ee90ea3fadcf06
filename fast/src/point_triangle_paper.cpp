#include "fdh/point_triangle/paper.hpp"

namespace fdh {
namespace {

// N = B - ((B-D)·n / n·n) n with n = DE × DF. A zero-area triangle gives NaN, and both readings
// then answer "no" (every comparison with NaN is false).
Vec3 projection_on_plane(const Vec3& b, const Vec3& d, const Vec3& e, const Vec3& f) {
  const Vec3 n = cross(e - d, f - d);
  return b - (dot(b - d, n) / dot(n, n)) * n;
}

}  // namespace

bool paper_literal(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f) {
  const Vec3 n = projection_on_plane(b0, d, e, f);
  const Vec3 bb = b1 - b0;
  if (dot(n - b0, bb) != 0) {  // N1 != 0: step (4)
    const Vec3 nb1 = b1 - n;
    return dot(nb1, nb1) <= 0;  // N3 <= 0
  }
  return dot(bb, d - b1) <= 0;  // N2 <= 0
}

bool paper_intended(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f) {
  const Vec3 n = projection_on_plane(b0, d, e, f);
  const Vec3 bb = b1 - b0;
  if (cross(n - b0, bb) == Vec3{}) return dot(bb, n - b1) <= 0;  // parallel (Fig. 3): N2 <= 0
  return dot(b1 - n, b0 - n) <= 0;                               // angled (Fig. 4): N3 <= 0
}

}  // namespace fdh
