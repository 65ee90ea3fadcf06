// The query's points as exact moving points: coordinates are polynomials in t (degree <= 1 each)
// with integer coefficients, after scaling every double by one power of two. Shared by the
// contact search (exact_ccd.cpp) and the minimum-separation search (exact_separation.cpp).
// Private to reference/.
#pragma once

#include <array>

#include "fdh/query.hpp"
#include "polynomial.hpp"

namespace fdh::exact {

// A point or vector whose coordinates are polynomials in t.
struct PVec {
  algebra::Poly x, y, z;
  bool is_zero() const { return x.is_zero() && y.is_zero() && z.is_zero(); }
};
inline PVec operator-(const PVec& a, const PVec& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline PVec cross(const PVec& a, const PVec& b) {
  using algebra::sum_of_products;
  return {sum_of_products({{a.y, b.z}, {a.z, b.y, true}}),
          sum_of_products({{a.z, b.x}, {a.x, b.z, true}}),
          sum_of_products({{a.x, b.y}, {a.y, b.x, true}})};
}
inline algebra::Poly dot(const PVec& a, const PVec& b) {
  return algebra::sum_of_products({{a.x, b.x}, {a.y, b.y}, {a.z, b.z}});
}

// The four moving points with their coordinates scaled by 2^scale into integers, the smallest
// scale >= 0 that does it: every condition of the searches is homogeneous in the coordinates
// (a minimum separation is scaled with them), so no sign changes. `scale` receives the power.
std::array<PVec, 4> integer_paths(const Query& q, long* scale = nullptr);

}  // namespace fdh::exact
