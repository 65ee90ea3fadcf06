#include "moving_points.hpp"

#include <algorithm>

namespace fdh::exact {

using algebra::Poly;

std::array<PVec, 4> integer_paths(const Query& q, long* scale) {
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
    v[i].x = Poly::linear(c[3 * i], c[3 * i + 12]);
    v[i].y = Poly::linear(c[3 * i + 1], c[3 * i + 13]);
    v[i].z = Poly::linear(c[3 * i + 2], c[3 * i + 14]);
  }
  return v;
}

}  // namespace fdh::exact
