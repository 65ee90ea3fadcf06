// FDH (fixed-direction hull, k-DOP) as in Han & Jia 2013 §2: for each direction d of a fixed set
// D, the interval [min d·p, max d·p] over the points. Stored FCL-style as flat arrays of
// per-slab extents so that the overlap test is a tight loop.
//
// Conservative under rounding: a Kdop built from double points contains the exact FDH of those
// points. Axis slabs are exact (a coordinate is its own projection). A diagonal projection
// (±x ± y) ± z rounds at most twice; see widening_of() for the bound and why it holds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "fdh/vec3.hpp"

namespace fdh {

struct Direction {
  int x, y, z;
};

// The 13 integer directions: 3 axes, 4 corner diagonals, 6 edge diagonals.
inline constexpr std::array<Direction, 13> kDirections = {{{1, 0, 0},
                                                           {0, 1, 0},
                                                           {0, 0, 1},  // axes
                                                           {1, 1, 1},
                                                           {1, 1, -1},
                                                           {1, -1, 1},
                                                           {1, -1, -1},  // corners
                                                           {1, 1, 0},
                                                           {1, -1, 0},
                                                           {1, 0, 1},
                                                           {1, 0, -1},
                                                           {0, 1, 1},
                                                           {0, 1, -1}}};  // edges

// Which of the 13 directions a k-DOP uses: 6 = axes, 14 = axes + corners, 18 = axes + edges,
// 26 = all.
template <int K>
constexpr std::array<int, K / 2> direction_indices() {
  static_assert(K == 6 || K == 14 || K == 18 || K == 26, "k must be 6, 14, 18 or 26");
  std::array<int, K / 2> idx{};
  int n = 0;
  for (int i = 0; i < 13; ++i) {
    const bool axis = i < 3, corner = i >= 3 && i < 7, edge = i >= 7;
    if (axis || (corner && (K == 14 || K == 26)) || (edge && (K == 18 || K == 26))) idx[n++] = i;
  }
  return idx;
}

inline bool is_valid_k(int k) {
  return k == 6 || k == 14 || k == 18 || k == 26;
}

// d·p in the order ((dx·px + dy·py) + dz·pz). The products are exact (d is 0 or ±1).
inline double project(const Direction& d, const Vec3& p) {
  return d.x * p.x + d.y * p.y + d.z * p.z;
}

// How far to push a diagonal slab outward, given mag = the largest |coordinate| of the points.
// Each projection is s2 = fl(fl(a+b)+c) with |a|,|b|,|c| <= mag. In the standard model
// (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., §2.2) its error is at most
// u|s1| + u|s2| <= 5.0001·u·mag, u = 2^-53. Additions never underflow with extra error (a
// subnormal sum is exact), so this holds for every finite mag <= 2^1020. The outward step
// fl(hi + w) itself rounds, and loses at most u|hi + w|; w = 16u·mag covers both:
// hi + w - u(3.0001·mag + w) >= hi + 5.0001·u·mag when w(1-u) >= 8.0002·u·mag. The extra
// denorm_min covers the product rounding down when 16u·mag is subnormal (the product by a power
// of two rounds as ldexp does, and costs one multiplication: refit calls this once per leaf).
inline double widening_of(double mag) {
  return mag * 0x1p-49 + std::numeric_limits<double>::denorm_min();
}

template <int K>
struct Kdop {
  static constexpr int kSlabs = K / 2;
  static constexpr std::array<int, kSlabs> kDirIndex = direction_indices<K>();

  std::array<double, kSlabs> lo, hi;

  static constexpr const Direction& direction(int slab) { return kDirections[kDirIndex[slab]]; }
  static constexpr bool is_exact_slab(int slab) { return kDirIndex[slab] < 3; }

  static Kdop empty() {
    Kdop b;
    b.lo.fill(std::numeric_limits<double>::infinity());
    b.hi.fill(-std::numeric_limits<double>::infinity());
    return b;
  }
};

// All 13 projections of p, in kDirections' order, each rounded exactly as project() rounds it
// ((x ± y) ± z; a zero term adds nothing), sharing the common sums. The hot loop of every
// refit.
inline std::array<double, 13> projections(const Vec3& p) {
  const double xpy = p.x + p.y, xmy = p.x - p.y;
  return {p.x, p.y, p.z,       xpy + p.z, xpy - p.z, xmy + p.z, xmy - p.z,
          xpy, xmy, p.x + p.z, p.x - p.z, p.y + p.z, p.y - p.z};
}

// Grows b to hold p's projections, the diagonal slabs pushed out by w (axis slabs are exact).
// min(v) - w and min(v - w) round alike (rounding is monotonic), so widening each point equals
// widening the box once, and keeps every slab in registers: the hot loop of every refit.
// Unrolled over the slabs at compile time.
template <int K, std::size_t... S>
inline void add_point_slabs(Kdop<K>& b, const std::array<double, 13>& v, double w,
                            std::index_sequence<S...>) {
  ((b.lo[S] = std::min(b.lo[S], Kdop<K>::is_exact_slab(S) ? v[Kdop<K>::kDirIndex[S]]
                                                          : v[Kdop<K>::kDirIndex[S]] - w),
    b.hi[S] = std::max(b.hi[S], Kdop<K>::is_exact_slab(S) ? v[Kdop<K>::kDirIndex[S]]
                                                          : v[Kdop<K>::kDirIndex[S]] + w)),
   ...);
}

template <int K>
inline void add_point(Kdop<K>& b, const Vec3& p, double w) {
  add_point_slabs(b, projections(p), w, std::make_index_sequence<Kdop<K>::kSlabs>{});
}

// Sets b to the box of the single point p, pushed out likewise.
template <int K, std::size_t... S>
inline void set_point_slabs(Kdop<K>& b, const std::array<double, 13>& v, double w,
                            std::index_sequence<S...>) {
  ((b.lo[S] = Kdop<K>::is_exact_slab(S) ? v[Kdop<K>::kDirIndex[S]] : v[Kdop<K>::kDirIndex[S]] - w,
    b.hi[S] = Kdop<K>::is_exact_slab(S) ? v[Kdop<K>::kDirIndex[S]] : v[Kdop<K>::kDirIndex[S]] + w),
   ...);
}

template <int K>
inline void set_point(Kdop<K>& b, const Vec3& p, double w) {
  set_point_slabs(b, projections(p), w, std::make_index_sequence<Kdop<K>::kSlabs>{});
}

// Sets b to the box of the segment p q (both ends), pushed out likewise: set_point(b, p, w)
// then add_point(b, q, w) in one pass that writes each slab once (min(a - w, c - w) and
// min(a, c) - w round alike). A swept particle's leaf: the hot loop of every cloth refit.
template <int K, std::size_t... S>
inline void set_segment_slabs(Kdop<K>& b, const std::array<double, 13>& u,
                              const std::array<double, 13>& v, double w,
                              std::index_sequence<S...>) {
  constexpr auto& dir = Kdop<K>::kDirIndex;
  ((b.lo[S] = Kdop<K>::is_exact_slab(S) ? std::min(u[dir[S]], v[dir[S]])
                                        : std::min(u[dir[S]], v[dir[S]]) - w,
    b.hi[S] = Kdop<K>::is_exact_slab(S) ? std::max(u[dir[S]], v[dir[S]])
                                        : std::max(u[dir[S]], v[dir[S]]) + w),
   ...);
}

template <int K>
inline void set_segment(Kdop<K>& b, const Vec3& p, const Vec3& q, double w) {
  set_segment_slabs(b, projections(p), projections(q), w,
                    std::make_index_sequence<Kdop<K>::kSlabs>{});
}

// Accumulates points, then widens the diagonal slabs once (not once per point).
// Precondition: every coordinate is finite with magnitude <= 2^1020.
template <int K>
class KdopBuilder {
 public:
  void add(const Vec3& p) {
    mag_ = std::max(mag_, max_abs(p));
    add_point(box_, p, 0.0);
  }
  Kdop<K> finish() const {
    Kdop<K> b = box_;
    const double w = widening_of(mag_);
    for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
      if (Kdop<K>::is_exact_slab(s)) continue;
      b.lo[s] -= w;
      b.hi[s] += w;
    }
    return b;
  }

 private:
  Kdop<K> box_ = Kdop<K>::empty();
  double mag_ = 0;
};

template <int K>
Kdop<K> kdop_of(const Vec3* pts, std::size_t n) {
  KdopBuilder<K> b;
  for (std::size_t i = 0; i < n; ++i) b.add(pts[i]);
  return b.finish();
}

// Union of two k-DOPs into m (which may be a or b), in one pass: min and max are exact, so
// containment is kept. In place because the trees' refit and build merge into their nodes: a
// Kdop returned by value, or copied then merged, costs more in stores than the merge itself.
template <int K>
void merge_into(Kdop<K>& m, const Kdop<K>& a, const Kdop<K>& b) {
  for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
    m.lo[s] = std::min(a.lo[s], b.lo[s]);
    m.hi[s] = std::max(a.hi[s], b.hi[s]);
  }
}

template <int K>
Kdop<K> merge(const Kdop<K>& a, const Kdop<K>& b) {
  Kdop<K> m;
  merge_into(m, a, b);
  return m;
}

// Closed slabs: touching counts as overlap.
template <int K>
bool slab_overlaps(const Kdop<K>& a, const Kdop<K>& b, int s) {
  return !(a.hi[s] < b.lo[s] || b.hi[s] < a.lo[s]);
}

// Every slab at once, two per vector register and without a branch: a tree traversal tests
// mostly boxes that do overlap, where an early exit saves nothing and its mispredicted branches
// cost more than the comparisons. Same answer as slab_overlaps() on every slab (NaN included:
// a comparison with NaN is false, so it separates nothing).
template <int K>
bool overlap(const Kdop<K>& a, const Kdop<K>& b) {
  using Pair = double __attribute__((vector_size(16)));
  using Mask = long long __attribute__((vector_size(16)));
  constexpr int kSlabs = Kdop<K>::kSlabs;
  Mask apart = {0, 0};
  for (int s = 0; s + 2 <= kSlabs; s += 2) {
    Pair alo, ahi, blo, bhi;
    std::memcpy(&alo, &a.lo[s], sizeof alo), std::memcpy(&ahi, &a.hi[s], sizeof ahi);
    std::memcpy(&blo, &b.lo[s], sizeof blo), std::memcpy(&bhi, &b.hi[s], sizeof bhi);
    apart |= (ahi < blo) | (bhi < alo);
  }
  bool meet = !(apart[0] | apart[1]);
  if (kSlabs % 2) meet &= slab_overlaps(a, b, kSlabs - 1);
  return meet;
}

// §3.1's early-out: test first the slab along which the motion makes separation most likely
// (for a cloth falling on a table, the y slab), then the rest.
template <int K>
bool overlap(const Kdop<K>& a, const Kdop<K>& b, int first_slab) {
  return slab_overlaps(a, b, first_slab) && overlap(a, b);
}

// The slab whose direction is most nearly parallel to `motion` (by |d·m| / |d|).
template <int K>
int most_aligned_slab(const Vec3& motion) {
  int best = 0;
  double best_score = -1;
  for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
    const Direction& d = Kdop<K>::direction(s);
    const double len = std::sqrt(double(d.x * d.x + d.y * d.y + d.z * d.z));
    const double score = std::fabs(project(d, motion)) / len;
    if (score > best_score) best = s, best_score = score;
  }
  return best;
}

// Calls f(std::integral_constant<int, K>{}) for a k chosen at run time.
template <class F>
decltype(auto) with_k(int k, F&& f) {
  switch (k) {
    case 6:
      return f(std::integral_constant<int, 6>{});
    case 14:
      return f(std::integral_constant<int, 14>{});
    case 18:
      return f(std::integral_constant<int, 18>{});
    case 26:
      return f(std::integral_constant<int, 26>{});
  }
  throw std::invalid_argument("k must be 6, 14, 18 or 26, not " + std::to_string(k));
}

// The direction of slab `slab` of a k-DOP, for code that picks k at run time.
inline Direction slab_direction(int k, int slab) {
  return with_k(k, [&](auto kc) { return Kdop<decltype(kc)::value>::direction(slab); });
}

}  // namespace fdh
