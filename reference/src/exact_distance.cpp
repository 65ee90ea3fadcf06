#include "fdh/exact/distance.hpp"

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/squared_distance_3.h>

#include <array>

namespace fdh::exact {
namespace {

using FT = CGAL::Exact_rational;
using K = CGAL::Simple_cartesian<FT>;
using Point = K::Point_3;
using Segment = K::Segment_3;

Point corner_at(const Query& q, int i, const FT& t) {
  const Vec3 &a = q.x[i], &b = q.x[i + 4];
  // FT: gmpxx expression templates would outlive the temporaries.
  const auto at = [&t](double u, double v) -> FT { return FT(u) + t * (FT(v) - FT(u)); };
  return {at(a.x, b.x), at(a.y, b.y), at(a.z, b.z)};
}

// Zero-length segments as the points they are: CGAL's segment formulas divide by the length.
FT point_segment(const Point& p, const Point& a, const Point& b) {
  if (a == b) return CGAL::squared_distance(p, a);
  return CGAL::squared_distance(p, Segment(a, b));
}

FT segment_segment(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
  if (a0 == a1) return point_segment(a0, b0, b1);
  if (b0 == b1) return point_segment(b0, a0, a1);
  return CGAL::squared_distance(Segment(a0, a1), Segment(b0, b1));
}

FT point_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  if (!CGAL::collinear(a, b, c)) return CGAL::squared_distance(p, K::Triangle_3(a, b, c));
  // A degenerate triangle is the union of its edges.
  FT d = point_segment(p, a, b);
  for (const FT& e : {point_segment(p, b, c), point_segment(p, c, a)})
    if (e < d) d = e;
  return d;
}

}  // namespace

int compare_distance_at(const Query& q, double t) {
  const FT time(t), delta(q.min_distance);
  std::array<Point, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = corner_at(q, i, time);
  const FT d2 = q.kind == QueryKind::VertexFace ? point_triangle(x[0], x[1], x[2], x[3])
                                                : segment_segment(x[0], x[1], x[2], x[3]);
  return CGAL::compare(d2, delta * delta);
}

}  // namespace fdh::exact
