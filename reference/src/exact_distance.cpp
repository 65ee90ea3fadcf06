#include "fdh/exact/distance.hpp"

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/squared_distance_3.h>

#include <array>
#include <cmath>
#include <sstream>

#include "fdh/exact/triangle_triangle.hpp"

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

Point point_of(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// The squared distance of two closed triangles that do not meet: every vertex against the
// other triangle, every edge against every edge of the other.
FT apart_squared(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  std::array<Point, 3> p, q;
  for (int i = 0; i < 3; ++i) p[i] = point_of(a[i]), q[i] = point_of(b[i]);
  FT d = point_triangle(p[0], q[0], q[1], q[2]);
  const auto least = [&d](const FT& e) {
    if (e < d) d = e;
  };
  for (int i = 0; i < 3; ++i) {
    if (i > 0) least(point_triangle(p[i], q[0], q[1], q[2]));
    least(point_triangle(q[i], p[0], p[1], p[2]));
    for (int j = 0; j < 3; ++j) least(segment_segment(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3]));
  }
  return d;
}

FT squared_distance_of(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  return triangles_intersect(a, b) ? FT(0) : apart_squared(a, b);
}

}  // namespace

TriangleDistance triangle_distance(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  const FT d2 = squared_distance_of(a, b);
  TriangleDistance out;
  std::ostringstream os;
  os << d2;
  out.squared = os.str();
  // The square roots of an enclosure of d2, each pushed one double outward (sqrt rounds to
  // nearest).
  const std::pair<double, double> i = CGAL::to_interval(d2);
  out.lo = i.first > 0 ? std::nextafter(std::sqrt(i.first), 0.0) : 0.0;
  out.hi = i.second > 0 ? std::nextafter(std::sqrt(i.second), HUGE_VAL) : 0.0;
  return out;
}

bool triangles_within(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b, double d) {
  const FT delta(d);
  return squared_distance_of(a, b) <= delta * delta;
}

int compare_distance_at(const Query& q, double t) {
  const FT time(t), delta(q.min_distance);
  std::array<Point, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = corner_at(q, i, time);
  const FT d2 = q.kind == QueryKind::VertexFace ? point_triangle(x[0], x[1], x[2], x[3])
                                                : segment_segment(x[0], x[1], x[2], x[3]);
  return CGAL::compare(d2, delta * delta);
}

}  // namespace fdh::exact
