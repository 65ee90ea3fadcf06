// `robust` continuous collision detection for moving vertex-face and edge-edge queries: floating
// point with rigorous error bounds decides most queries; the rest go to the exact test that the
// caller passes in (fdh::exact::ccd_hit from reference/ in this project). So its verdict is the
// exact one: no false negatives and no false positives.
//
// The filter, in three stages (docs/methods.md):
// 1. The coplanarity cubic f(t) in Bernstein form on [0, 1]. Its four coefficients are
//    determinants of vertex differences at t = 0 and t = 1 (and means of three), each with a
//    static error bound (Shewchuk's orient3d analysis). All four certainly of one sign: f has
//    no root, so no.
// 2. Root isolation by de Casteljau subdivision of that Bernstein form, the error bound carried
//    along: a piece of one certain sign holds no root; one certain sign variation with opposite
//    ends holds exactly one. Each root is narrowed by halving, then the inside conditions g_i
//    (>= 0 at a coplanar time iff contact) are bounded over its piece by interval arithmetic
//    (fdh/interval.hpp): all > 0, contact; one < 0, none there. A piece where f is uncertain is
//    still excluded when some g_i < 0 over it. Otherwise: uncertain. The filter gives up
//    early where it would almost never succeed, since its time adds to the fallback's: after
//    four interval evaluations of the g_i, or as soon as f's sign is uncertain over a whole
//    piece (coplanar motion) or at t = 0 or 1 (a contact at the very start or end).
// 3. Where the coordinates are, after one common power of two, integers of at most 32 bits (the
//    hard cases are mostly made so: coplanar motion, a vertex sliding on an edge, parallel
//    edges, a triangle or edge shrinking to a point), the same search exactly in checked
//    128-bit integers: f's exact Bernstein coefficients, roots at dyadic times found exactly by
//    subdivision, those of degree-2 conditions as fractions or exact quadratic roots, the
//    contact at an exact time on integers (as reference/'s). It declines where a value would
//    overflow or a root is neither exact nor settled by intervals.
#pragma once

#include "fdh/filtered.hpp"
#include "fdh/query.hpp"

namespace fdh {

Filtered robust_ccd_filter(const Query& q);

// The filter with what it learns of the earliest contact t* on the way (fdh/ccd/toi.hpp): no
// contact in [0, t0); with Yes, t* <= t1 as well; `enclosed`: t0 <= t* <= t1 certified, with
// t1 - t0 <= width (its own isolated root narrowed, extended precision where doubles cannot
// show f's sign that close to it). The verdict is robust_ccd_filter's.
struct FilteredToi {
  Filtered verdict = Filtered::Uncertain;
  double t0 = 0, t1 = 1;
  bool enclosed = false;
};
FilteredToi robust_ccd_toi_filter(const Query& q, double width);

// The stages of the verdict above, in the order a query meets them, and the one that decides a
// query (with δ = q.min_distance > 0, the search within δ counts as the subdivision): for
// measurement (bench/robust_stages.cpp, docs/performance.md "robust by stage"), never a verdict.
enum class RobustStage {
  Volume,       // stage 1: f's Bernstein coefficients of one certain sign
  Subdivision,  // stage 2: root isolation and intervals
  Integer,      // stage 3: exact on small integers (checked 128-bit)
  Exact,        // none: the caller's exact test
};
RobustStage robust_ccd_stage(const Query& q);

using CcdTest = bool (*)(const Query& q);

inline bool robust_ccd(const Query& q, CcdTest exact_fallback) {
  return or_exact(robust_ccd_filter(q), [&] { return exact_fallback(q); });
}

}  // namespace fdh
