// The time of impact (TOI) of a moving vertex-face or edge-edge query: whether the primitives
// touch during the step, and an enclosure [t_lo, t_hi] of the earliest contact time t* in step
// units (docs/methods.md, "Time of impact"). A solver advances to t_lo: never late, and 0 only
// when t* = 0.
#pragma once

#include "fdh/query.hpp"

namespace fdh {

struct Toi {
  bool hit = false;
  // With a hit: t_lo <= t* <= t_hi, both in [0, 1]. Without: both 1 (the whole step is free).
  double t_lo = 1, t_hi = 1;
};

// The default width of `robust`'s enclosure: 2^-30 of the step.
inline constexpr double kDefaultToiWidth = 0x1p-30;

// The narrowest width asked for: the doubles around t* in [1/2, 1] are 2^-53 apart, so an
// irrational t* next to a double needs the two doubles on either side of that one.
inline constexpr double kMinToiWidth = 0x1p-52;

// The exact fallback of `robust_ccd_toi`: the exact verdict and an enclosure of t* no wider
// than `width`, searched in the window [t0, t1] of the step that the filter has already narrowed
// (the caller guarantees no contact lies in [0, t0), and that a contact, if any, lies in
// [t0, t1] unless t1 = 1). fdh::exact::ccd_toi (reference/) in this project.
using ExactToi = Toi (*)(const Query& q, double t0, double t1, double width);

// `robust`'s certified TOI: the exact verdict, and t_lo <= t* <= t_hi with t_hi - t_lo <= width
// (kMinToiWidth <= width <= 1; std::invalid_argument otherwise), t_lo > 0 unless t* = 0. The
// floating-point filter narrows its own isolated root where it can; the rest goes to exact_fallback
// with the window it has narrowed.
Toi robust_ccd_toi(const Query& q, double width, ExactToi exact_fallback);

// `float-cubic`'s TOI: its first root in [0, 1] at which its own contact test passes, as
// t_lo = t_hi. The naive baseline: neither late-proof nor exact.
Toi float_cubic_toi(const Query& q);

}  // namespace fdh
