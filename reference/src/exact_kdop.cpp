#include "fdh/exact/kdop.hpp"

#include <CGAL/Exact_rational.h>

#include <cmath>

#include "fdh/kdop.hpp"

namespace fdh::exact {
namespace {

using Q = CGAL::Exact_rational;

struct Extent {
  Q lo, hi;
};

Q exact_projection(const Direction& d, const Vec3& p) {
  return Q(d.x) * Q(p.x) + Q(d.y) * Q(p.y) + Q(d.z) * Q(p.z);
}

std::vector<Direction> directions_of(int k) {
  std::vector<Direction> dirs;
  for (int s = 0; s < k / 2; ++s) dirs.push_back(slab_direction(k, s));
  return dirs;
}

// Precondition: n >= 1.
std::vector<Extent> exact_extents(const std::vector<Direction>& dirs, const Vec3* pts,
                                  std::size_t n) {
  std::vector<Extent> ext;
  for (const Direction& d : dirs) {
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

// lo <= e.lo and e.hi <= hi, for any doubles a peer may report: an infinite bound holds on its
// side, NaN holds nowhere (Gmpq takes finite doubles only).
bool contains(double lo, const Extent& e, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return false;
  const bool lo_ok = std::isinf(lo) ? lo < 0 : Q(lo) <= e.lo;
  const bool hi_ok = std::isinf(hi) ? hi > 0 : e.hi <= Q(hi);
  return lo_ok && hi_ok;
}

bool overlap(const std::vector<Extent>& a, const std::vector<Extent>& b) {
  for (std::size_t s = 0; s < a.size(); ++s)
    if (a[s].hi < b[s].lo || b[s].hi < a[s].lo) return false;
  return true;
}

}  // namespace

int first_uncontained_slab(const std::vector<Direction>& dirs, const Vec3* pts, std::size_t n,
                           const double* lo, const double* hi) {
  if (n == 0) return -1;
  const std::vector<Extent> ext = exact_extents(dirs, pts, n);
  for (std::size_t s = 0; s < dirs.size(); ++s)
    if (!contains(lo[s], ext[s], hi[s])) return int(s);
  return -1;
}

int first_uncontained_slab(int k, const Vec3* pts, std::size_t n, const double* lo,
                           const double* hi) {
  return first_uncontained_slab(directions_of(k), pts, n, lo, hi);
}

bool kdops_overlap(const std::vector<Direction>& dirs, const Vec3* a, std::size_t na, const Vec3* b,
                   std::size_t nb) {
  if (na == 0 || nb == 0) return false;
  return overlap(exact_extents(dirs, a, na), exact_extents(dirs, b, nb));
}

bool kdops_overlap(int k, const Vec3* a, std::size_t na, const Vec3* b, std::size_t nb) {
  return kdops_overlap(directions_of(k), a, na, b, nb);
}

std::vector<std::pair<int, int>> overlapping_pairs(int k, const std::vector<std::vector<Vec3>>& a,
                                                   const std::vector<std::vector<Vec3>>& b) {
  const std::vector<Direction> dirs = directions_of(k);
  const auto extents = [&dirs](const std::vector<std::vector<Vec3>>& sets) {
    std::vector<std::vector<Extent>> out;
    for (const auto& s : sets)
      out.push_back(s.empty() ? std::vector<Extent>{} : exact_extents(dirs, s.data(), s.size()));
    return out;
  };
  const auto ea = extents(a), eb = extents(b);
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (!a[i].empty() && !b[j].empty() && overlap(ea[i], eb[j]))
        pairs.push_back({int(i), int(j)});
  return pairs;
}

}  // namespace fdh::exact
