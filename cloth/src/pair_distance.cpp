#include "fdh/cloth/pair_distance.hpp"

#include "fdh/closest_points.hpp"

namespace fdh::cloth {

PairClosest pair_closest(QueryKind kind, const std::array<Vec3, 4>& p) {
  PairClosest r;
  if (kind == QueryKind::VertexFace) {
    const ClosestPoints c = closest_point_triangle(p[0], p[1], p[2], p[3]);
    r.w = {1, 1 - c.s - c.u, c.s, c.u};
  } else {
    const ClosestPoints c = closest_segments(p[0], p[1], p[2], p[3]);
    r.w = {1 - c.s, c.s, 1 - c.u, c.u};
  }
  const int split = kind == QueryKind::VertexFace ? 1 : 2;  // the second primitive's first point
  Vec3 a, b;
  for (int i = 0; i < 4; ++i) (i < split ? a : b) += r.w[i] * p[i];
  r.dir = a - b;
  r.distance = norm(r.dir);
  return r;
}

}  // namespace fdh::cloth
