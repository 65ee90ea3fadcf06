// Han & Jia 2013 §3.2: does particle B, moving to B' in one step, hit the still triangle DEF?
// N is B's projection on the plane of DEF. Two readings of the printed steps; docs/methods.md
// says where each fails. Neither checks that the crossing lies inside DEF: the paper leaves that
// to the FDH tree (see `classify --gate`).
#pragma once

#include "fdh/vec3.hpp"

namespace fdh {

// Exactly as printed. N1 = BN·BB'. If N1 != 0: hit iff N3 = NB'·NB' <= 0.
// Else: hit iff N2 = BB'·B'D' <= 0, reading D' as D (the triangle does not move).
bool paper_literal(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f);

// The reading that Figs. 3 and 4 support. Parallel motion (BN × BB' = 0): hit iff
// N2 = BB'·B'N <= 0, B' at or past N. Otherwise hit iff N3 = NB'·NB <= 0, B' not strictly on
// B's side of the plane.
bool paper_intended(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f);

}  // namespace fdh
