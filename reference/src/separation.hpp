// The exact minimum-separation CCD: the twins of exact::ccd, ccd_hit, ccd_toi and
// compare_with_toi (fdh/exact/ccd.hpp) for a query with q.min_distance = δ > 0, which those
// entry points call. The question: do the closed primitives come within Euclidean distance δ at
// some time of [t0, t1], and when first (t*_δ)? The algebra is in exact_separation.cpp and
// docs/methods.md ("Minimum separation"). Private to reference/.
#pragma once

#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/query.hpp"

namespace fdh::exact {

// Each throws std::invalid_argument for δ that is not finite and > 0, or a bad window; the
// contracts are those of the entry points of the same role.
CcdContact separation_ccd(const Query& q, const CcdOptions& options);
bool separation_hit(const Query& q);
Toi separation_toi(const Query& q, double t0, double t1, double width);
int separation_compare_with_toi(const Query& q, double t);

}  // namespace fdh::exact
