// `robust` continuous collision detection for moving vertex-face and edge-edge queries: floating
// point with rigorous error bounds decides most queries; the rest go to the exact test that the
// caller passes in (fdh::exact::ccd_hit from reference/ in this project). So its verdict is the
// exact one: no false negatives and no false positives.
//
// The filter, in two stages (docs/methods.md):
// 1. The coplanarity cubic f(t) in Bernstein form on [0, 1]. Its four coefficients are sums of
//    3x3 determinants of vertex differences at t = 0 and t = 1, each with a static error bound
//    (Shewchuk's orient3d analysis). All four certainly of one sign: f has no root, so no.
// 2. Bisection of [0, 1] with interval arithmetic (fdh/interval.hpp) on f and on the inside
//    conditions g_i (>= 0 at a coplanar time iff contact). A piece where f != 0, or where some
//    g_i < 0, holds no contact. A piece where f certainly changes sign and every g_i > 0 holds
//    one. Every piece excluded: no. One piece certified: yes. Otherwise: uncertain.
#pragma once

#include "fdh/filtered.hpp"
#include "fdh/query.hpp"

namespace fdh {

Filtered robust_ccd_filter(const Query& q);

using CcdTest = bool (*)(const Query& q);

inline bool robust_ccd(const Query& q, CcdTest exact_fallback) {
  return or_exact(robust_ccd_filter(q), [&] { return exact_fallback(q); });
}

}  // namespace fdh
