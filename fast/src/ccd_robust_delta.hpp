// `robust` within the minimum separation δ = q.min_distance > 0 (docs/methods.md, "Minimum
// separation: the robust filter"): the parts of robust_ccd_toi_filter (ccd_robust.cpp) that
// only δ > 0 reaches. Private to fast/.
#pragma once

#include "fdh/ccd/robust.hpp"

namespace fdh {

// True if the primitives certainly stay farther apart than δ throughout the step, given
// volume_lo <= |f(t)| on [0, 1] for the coplanarity cubic f (0 when f's sign is uncertain).
bool apart_by_volume(const Query& q, double volume_lo);

// The time search within δ: pieces of [0, min(contact_by, 1)] in time order (contact_by: a time
// by which the primitives certainly touch, > 1 if none is known), each excluded where rigorous
// bounds keep the distance > δ over it, or settled by a time where they keep it <= δ. With width >
// 0, what it learns of t*_δ too (FilteredToi's promises); width = 0: the verdict alone.
FilteredToi robust_delta_search(const Query& q, double width, double contact_by);

}  // namespace fdh
