// Drawing small integers and dyadic numbers through RapidCheck, inside a generator
// (rc::gen::exec), shrinking toward small values. Private to fdh_gen.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>

#include "fdh/vec3.hpp"

namespace fdh::verify {

// An integer in [lo, hi] that shrinks toward the value nearest 0, alternating sides (c, c+1,
// c-1, c+2, ...), so that shrunk counterexamples have small coordinates rather than lo's.
inline int pick(int lo, int hi) {
  const int k = *rc::gen::inRange(0, hi - lo + 1);
  const int c = std::clamp(0, lo, hi), up = hi - c, down = c - lo, m = std::min(up, down);
  if (k <= 2 * m) return (k % 2) ? c + (k + 1) / 2 : c - k / 2;
  return up > down ? c + m + (k - 2 * m) : c - m - (k - 2 * m);
}
// A multiple of 2^-bits in [lo, hi] (lo, hi integers in units of 2^-bits).
inline double dyadic(int lo, int hi, int bits) {
  return std::ldexp(double(pick(lo, hi)), -bits);
}
// A point with integer coordinates in [-r, r].
inline Vec3 small_point(int r) {
  return Vec3{double(pick(-r, r)), double(pick(-r, r)), double(pick(-r, r))};
}

}  // namespace fdh::verify
