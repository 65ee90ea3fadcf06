// The earliest of several candidate contact times, each a root (exact, or alone in an open
// interval; polynomial.hpp's Root): the earliest lies in [min lo, min hi]. Shared by the contact
// search (exact_ccd.cpp) and the minimum-separation search (exact_separation.cpp), which give it
// their candidates in any container of Roots. Private to reference/.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"
#include "polynomial.hpp"

namespace fdh::exact {

namespace earliest_detail {

// Bounds as doubles, outward: get_d truncates, which rounds down for q >= 0.
inline double up(const mpq_class& q) {
  const double d = q.get_d();
  return mpq_class(d) < q ? std::nextafter(d, 2.0) : d;
}

// The bits that make an exact interval narrower than `width`, with two more for the outward
// rounding to doubles (each end moves by less than 2^-53 in [0, 1]).
inline unsigned long bits_for(double width) {
  return unsigned(std::max(0, -std::ilogb(width))) + 2;
}

// A dyadic rounded to a double downward or upward: to nearest by its leading bits, then one
// step where that went the wrong way.
inline double rounded(const algebra::Dyadic& x, bool upward) {
  long e = 0;
  const double m = x.a.frexp(&e);
  double d = std::ldexp(m, int(e - long(x.k)));
  const int c = algebra::compare(algebra::Dyadic::of(d), x);
  if (upward ? c < 0 : c > 0) d = std::nextafter(d, upward ? 2.0 : -1.0);
  return d;
}

}  // namespace earliest_detail

// The earliest candidate as doubles, outward, refined until they are at most `width` apart and
// t_lo > 0 unless t* = 0 (see ccd_toi). No strings, no rationals: dyadics only. Toi{} for none.
template <class Roots>
Toi earliest_toi(Roots& found, double width) {
  using earliest_detail::rounded;
  if (found.empty()) return Toi{};
  for (unsigned long bits = earliest_detail::bits_for(width);; bits += 8) {
    algebra::Dyadic lo, hi;
    bool first = true;
    for (algebra::Root& r : found) {
      algebra::narrow_to_doubles(r);  // mostly narrow enough at once
      algebra::refine(r, bits);
      algebra::Dyadic rl = r.lo(), rh = r.hi();
      if (first || algebra::compare(rl, lo) < 0) lo = std::move(rl);
      if (first || algebra::compare(rh, hi) < 0) hi = std::move(rh);
      first = false;
    }
    const Toi t{true, rounded(lo, false), rounded(hi, true)};
    // t_lo > 0 unless t* = 0: a contact just after 0 needs as many bits as it is close to 0
    // (one below 2^-1074, the smallest double, keeps t_lo = 0: no double lies below it).
    if (t.t_hi - t.t_lo <= width && (t.t_lo > 0 || t.t_hi == 0 || bits > 1100)) return t;
    if (bits > 1100)  // the interval holds two doubles apart by > 2^-52 only if wider than that
      throw std::logic_error("ccd_toi: the contact time did not narrow");
  }
}

// The earliest candidate as exact fractions, refined to width < 2^-bits (bits = 0: as found).
// May be called again with more bits: the candidates' intervals are refined in place.
template <class Roots>
CcdContact earliest_contact(Roots& found, unsigned long bits, bool want_time) {
  CcdContact out;
  if (found.empty()) return out;
  out.hit = true;
  if (!want_time) return out;
  mpq_class lo = 2, hi = 2;
  for (algebra::Root& r : found) {
    if (bits > 0) algebra::refine(r, bits);
    const mpq_class rl = r.lo().value(), rh = r.hi().value();
    if (rl < lo) lo = rl;
    if (rh < hi) hi = rh;
  }
  out.time_lo = lo.get_str();
  out.time_hi = hi.get_str();
  out.time_lo_down = lo.get_d();
  out.time_hi_up = earliest_detail::up(hi);
  return out;
}

// Where the window's end t1 lies against the earliest candidate t* found in [t0, t1] (there must
// be one): 0 if t* = t1, +1 if t* < t1. A candidate is exact at t1 or lies in an open interval
// (lo, hi) with hi <= t1 (polynomial.hpp's Root), so no refinement is needed.
template <class Roots>
int window_end_against_earliest(const Roots& found, const algebra::Dyadic& t1) {
  for (const algebra::Root& r : found)
    if (!r.exact() || r.lo().value() != t1.value()) return 1;
  return 0;
}

}  // namespace fdh::exact
