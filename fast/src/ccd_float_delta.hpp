// float-cubic within δ (q.min_distance > 0), the naive floating-point baseline of issue 30: see
// ccd_float_delta.cpp. Private to fast/: reached through float_cubic and float_cubic_toi.
#pragma once

#include "fdh/ccd/toi.hpp"

namespace fdh {

// The first root in [0, 1] of a feature pair's "within δ" polynomial at which its region test
// passes (0 if one is within δ at the start), as t_lo = t_hi; none: no hit.
Toi float_first_within(const Query& q);

}  // namespace fdh
