#include "fdh/exact/kdop.hpp"

#include <CGAL/Exact_rational.h>

#include <vector>

#include "fdh/kdop.hpp"

namespace fdh::exact {
namespace {

using Q = CGAL::Exact_rational;

Q exact_projection(const Direction& d, const Vec3& p) {
  return Q(d.x) * Q(p.x) + Q(d.y) * Q(p.y) + Q(d.z) * Q(p.z);
}

struct Extent {
  Q lo, hi;
};

std::vector<Extent> exact_extents(int k, const Vec3* pts, std::size_t n) {
  std::vector<Extent> ext;
  for (int s = 0; s < k / 2; ++s) {
    const Direction d = slab_direction(k, s);
    Extent e{exact_projection(d, pts[0]), exact_projection(d, pts[0])};
    for (std::size_t i = 1; i < n; ++i) {
      const Q v = exact_projection(d, pts[i]);
      if (v < e.lo) e.lo = v;
      if (v > e.hi) e.hi = v;
    }
    ext.push_back(e);
  }
  return ext;
}

}  // namespace

int first_uncontained_slab(int k, const Vec3* pts, std::size_t n, const double* lo,
                           const double* hi) {
  if (n == 0) return -1;
  const std::vector<Extent> ext = exact_extents(k, pts, n);
  for (int s = 0; s < k / 2; ++s)
    if (!(Q(lo[s]) <= ext[s].lo && ext[s].hi <= Q(hi[s]))) return s;
  return -1;
}

bool kdops_overlap(int k, const Vec3* a, std::size_t na, const Vec3* b, std::size_t nb) {
  if (na == 0 || nb == 0) return false;
  const std::vector<Extent> ea = exact_extents(k, a, na), eb = exact_extents(k, b, nb);
  for (int s = 0; s < k / 2; ++s)
    if (ea[s].hi < eb[s].lo || eb[s].hi < ea[s].lo) return false;
  return true;
}

}  // namespace fdh::exact
