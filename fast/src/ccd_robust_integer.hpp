// `robust`'s integer stage, between its subdivision and the exact fallback (docs/methods.md,
// "The integer stage"): a contact query whose coordinates are, after one common power of two,
// integers of at most kMaxIntegerBits bits, decided exactly in checked 128-bit integers. The
// cases that defeat floating point are exact there: the cubic f identically 0 (coplanar motion)
// or with a root at a dyadic time (a multiple root, a contact on an edge), a vertex sliding on an
// edge's line, parallel edges. Where a value would not fit, or a root is neither a fraction it
// can find nor settled by intervals over its isolating piece, it declines (Uncertain). Private
// to fast/.
#pragma once

#include "fdh/filtered.hpp"
#include "fdh/query.hpp"

namespace fdh {

constexpr int kMaxIntegerBits = 32;

struct IntegerToi {
  Filtered verdict = Filtered::Uncertain;
  // With Yes and `exact`: the earliest contact t* lies in [t_lo, t_hi], at most 2^-52 wide
  // (t* itself when it is a double), t_lo > 0 unless t* = 0.
  bool exact = false;
  double t_lo = 0, t_hi = 1;
};

// The query at contact (q.min_distance is not read). With want_time, the earliest contact too.
IntegerToi robust_ccd_integer(const Query& q, bool want_time);

}  // namespace fdh
