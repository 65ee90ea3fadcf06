// `float-cubic`: the classic floating-point continuous collision test of Provot (1997) and
// Bridson, Fedkiw and Anderson (2002), kept as the naive baseline that we measure. Solve the
// coplanarity cubic in doubles for its roots in [0, 1], then test, in time order, whether the
// primitives touch at each root: barycentric coordinates for vertex-face, the two segment
// parameters for edge-edge, with no tolerance. Parallel edges and zero-area triangles at a root
// count as no contact; a cubic that is identically zero (coplanar throughout) is tested at
// t = 0 and t = 1 only. Its misses and false alarms are what `robust` exists to remove.
#pragma once

#include "fdh/query.hpp"

namespace fdh {

bool float_cubic(const Query& q);

}  // namespace fdh
