// The closest points of two of the cloth's primitives at one instant, in plain floating point:
// a vertex and a triangle, or two edges. The self-collision pass uses them to see which pairs
// lie within the gap at the start of a step, to push such pairs apart, and to report the
// smallest distance kept; none of that decides a contact (robust CCD does,
// fdh/ccd/robust.hpp), so rounding here costs at most a stop earlier or later, never a crossing.
#pragma once

#include <array>

#include "fdh/query.hpp"
#include "fdh/vec3.hpp"

namespace fdh::cloth {

// The closest points as weights of the four points, each primitive's summing to 1: the first
// primitive's point is the sum of w[i] p[i] over its points (vertex–face: the vertex, p[0];
// edge–edge: p[0], p[1]), the second's over the rest. `dir` points from the second primitive's
// point to the first's; distance = |dir|.
struct PairClosest {
  std::array<double, 4> w{};
  Vec3 dir;
  double distance = 0;
};

// The weights of fdh/closest_points.hpp's closest points (Ericson, §5.1.5 and §5.1.9).
PairClosest pair_closest(QueryKind kind, const std::array<Vec3, 4>& p);

inline double pair_distance(QueryKind kind, const std::array<Vec3, 4>& p) {
  return pair_closest(kind, p).distance;
}

}  // namespace fdh::cloth
