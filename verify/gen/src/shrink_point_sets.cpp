#include "fdh/gen/shrink_point_sets.hpp"

#include <cmath>
#include <cstdlib>

#include "fdh/gen/short_doubles.hpp"

namespace fdh::verify {
namespace {

long coordinate_size(double v) {
  if (v == 0 || !std::isfinite(v)) return 0;
  return significant_bits(v) + std::abs(std::ilogb(v)) + 1;
}

template <class F>
PointSets mapped(const PointSets& sets, F f) {
  PointSets out = sets;
  for (auto& set : out)
    for (Vec3& p : set) p = f(p);
  return out;
}

// The simpler variants of `sets`, roughly in the order of how much each simplifies.
std::vector<PointSets> candidates(const PointSets& sets) {
  std::vector<PointSets> out;
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (std::size_t i = 0; sets[s].size() > 1 && i < sets[s].size(); ++i) {
      PointSets c = sets;
      c[s].erase(c[s].begin() + long(i));
      out.push_back(std::move(c));
    }
  const Vec3 first = sets.front().front();
  for (int bits : {1, 2, 4, 8, 16, 32, 53})  // a common translation toward the origin
    for (int axis = 0; axis < 3; ++axis) {
      const double t = with_bits(first[axis], bits, Rounding::Nearest);
      out.push_back(mapped(sets, [&](Vec3 p) {
        double xyz[3] = {p.x, p.y, p.z};
        xyz[axis] -= t;
        return Vec3{xyz[0], xyz[1], xyz[2]};
      }));
    }
  for (int e : {-8, -1, 1, 8})  // toward exponent 0
    out.push_back(mapped(sets, [e](Vec3 p) { return std::ldexp(1.0, e) * p; }));
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (std::size_t i = 0; i < sets[s].size(); ++i)
      for (int axis = 0; axis < 3; ++axis)
        for (int bits : {0, 1, 2, 4, 8, 16, 24, 32, 40, 48}) {
          PointSets c = sets;
          Vec3& p = c[s][i];
          double xyz[3] = {p.x, p.y, p.z};
          xyz[axis] = bits ? with_bits(xyz[axis], bits, Rounding::Nearest) : 0.0;
          p = {xyz[0], xyz[1], xyz[2]};
          out.push_back(std::move(c));
        }
  return out;
}

}  // namespace

long point_sets_size(const PointSets& sets) {
  long n = 0;
  for (const auto& set : sets)
    for (const Vec3& p : set)
      n += 1000 + coordinate_size(p.x) + coordinate_size(p.y) + coordinate_size(p.z);
  return n;
}

PointSets shrink_point_sets(PointSets sets, const std::function<bool(const PointSets&)>& fails,
                            int max_evaluations) {
  for (bool improved = true; improved && max_evaluations > 0;) {
    improved = false;
    const long size = point_sets_size(sets);
    for (PointSets& c : candidates(sets)) {
      if (point_sets_size(c) >= size) continue;
      if (--max_evaluations < 0) break;
      if (!fails(c)) continue;
      sets = std::move(c);
      improved = true;
      break;
    }
  }
  return sets;
}

}  // namespace fdh::verify
