// The query's points as exact moving points: coordinates are polynomials in t (degree <= 1 each)
// with integer coefficients, after scaling every double by one power of two. Shared by the
// contact search (exact_ccd.cpp) and the minimum-separation search (exact_separation.cpp).
// Private to reference/.
#pragma once

#include <algorithm>
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
// Inline, as it was inside exact_ccd.cpp: out of line, the contact test's median time grew by a
// few percent (fdhcert classify --methods exact --time).
inline std::array<PVec, 4> integer_paths(const Query& q, long* scale = nullptr) {
  algebra::Binary d[24];  // x = m 2^e; scaled by 2^k, each is the integer m 2^(e + k)
  long k = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 3; ++j) {
      algebra::Binary& e = d[3 * i + j];
      e = algebra::Binary::of(j == 0 ? q.x[i].x : j == 1 ? q.x[i].y : q.x[i].z);
      if (e.m != 0) k = std::max(k, -long(e.e));
    }
  algebra::Int c[24];
  for (int i = 0; i < 24; ++i)
    if (d[i].m != 0) mul_2exp(c[i], algebra::Int(d[i].m), (unsigned long)(d[i].e + k));
  if (scale != nullptr) *scale = k;
  std::array<PVec, 4> v;
  for (int i = 0; i < 4; ++i) {
    v[i].x = algebra::Poly::linear(c[3 * i], c[3 * i + 12]);
    v[i].y = algebra::Poly::linear(c[3 * i + 1], c[3 * i + 13]);
    v[i].z = algebra::Poly::linear(c[3 * i + 2], c[3 * i + 14]);
  }
  return v;
}

}  // namespace fdh::exact
