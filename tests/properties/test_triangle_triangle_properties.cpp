// `robust`'s static triangle-triangle test (fdh/triangle_triangle.hpp) equals its exact twin,
// CGAL's do_intersect (exact::triangles_intersect), on random, coplanar (z equal), touching,
// shared-plane and zero-area triangles; the edge it names does meet the other triangle.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "fdh/exact/point_triangle.hpp"
#include "fdh/exact/triangle_triangle.hpp"
#include "fdh/triangle_triangle.hpp"

namespace fdh {
namespace {

// Small integers (halved): contacts, shared planes and zero areas are frequent, and every
// construction below stays exact in doubles.
rc::Gen<double> small() {
  return rc::gen::map(rc::gen::inRange(-6, 7), [](int i) { return 0.5 * i; });
}
rc::Gen<Vec3> small_point() {
  return rc::gen::apply(
      [](double x, double y, double z) {
        return Vec3{x, y, z};
      },
      small(), small(), small());
}
Vec3 any_point() {
  return {*rc::gen::inRange(-1000, 1001) / 997.0, *rc::gen::inRange(-1000, 1001) / 991.0,
          *rc::gen::inRange(-1000, 1001) / 983.0};
}

void check_pair(const Triangle3& a, const Triangle3& b) {
  const bool exact = exact::triangles_intersect(a, b);
  const int e = robust_triangle_triangle_edge(a, b, exact::point_triangle_hit);
  RC_ASSERT((e >= 0) == exact);
  RC_ASSERT(robust_triangles_intersect(b, a, exact::point_triangle_hit) == exact);
  RC_ASSERT(exact::triangles_intersect(b, a) == exact);
  if (e < 0) return;
  const Triangle3 &s = e < 3 ? a : b, &t = e < 3 ? b : a;
  RC_ASSERT(exact::point_triangle_hit(s[e % 3], s[(e + 1) % 3], t[0], t[1], t[2]));
}

TEST(TriangleTriangleProperties, RobustEqualsExactOnRandomTriangles) {
  EXPECT_TRUE(rc::check("triangle-triangle/random", [] {
    const bool grid = *rc::gen::arbitrary<bool>();
    Triangle3 a, b;
    for (Vec3& p : a) p = grid ? *small_point() : any_point();
    for (Vec3& p : b) p = grid ? *small_point() : any_point();
    check_pair(a, b);
  }));
}

TEST(TriangleTriangleProperties, RobustEqualsExactOnFlatTriangles) {
  EXPECT_TRUE(rc::check("triangle-triangle/coplanar-z", [] {
    const double z = *rc::gen::element(0.0, 0.1, -3.7, 1e-3);  // exactly flat: z equal
    Triangle3 a, b;
    for (Vec3& p : a) p = {*small(), *small(), z};
    for (Vec3& p : b) p = {*small(), *small(), z};
    check_pair(a, b);
  }));
}

TEST(TriangleTriangleProperties, RobustEqualsExactOnASharedPlane) {
  EXPECT_TRUE(rc::check("triangle-triangle/shared-plane", [] {
    // Points o + i u + j v with small integers: one tilted plane, exactly.
    const Vec3 o = *small_point(), u = *small_point(), v = *small_point();
    const auto in_plane = [&] {
      const int i = *rc::gen::inRange(-3, 4), j = *rc::gen::inRange(-3, 4);
      return o + double(i) * u + double(j) * v;
    };
    const Triangle3 a{in_plane(), in_plane(), in_plane()}, b{in_plane(), in_plane(), in_plane()};
    check_pair(a, b);
  }));
}

TEST(TriangleTriangleProperties, RobustEqualsExactOnTouchingTriangles) {
  EXPECT_TRUE(rc::check("triangle-triangle/touching", [] {
    Triangle3 a, b;
    for (Vec3& p : a) p = *small_point();
    for (Vec3& p : b) p = *small_point();
    // One of b's corners on a's corner, edge midpoint or centroid-like point (dyadic: exact).
    const int i = *rc::gen::inRange(0, 3), j = *rc::gen::inRange(0, 3);
    switch (*rc::gen::inRange(0, 3)) {
      case 0:
        b[i] = a[j];
        break;
      case 1:
        b[i] = 0.5 * (a[j] + a[(j + 1) % 3]);
        break;
      default:
        b[i] = 0.25 * (a[0] + a[1]) + 0.5 * a[2];
    }
    check_pair(a, b);
  }));
}

TEST(TriangleTriangleProperties, RobustEqualsExactOnZeroAreaTriangles) {
  EXPECT_TRUE(rc::check("triangle-triangle/degenerate", [] {
    Triangle3 a, b;
    for (Vec3& p : a) p = *small_point();
    for (Vec3& p : b) p = *small_point();
    // a collinear (its third corner on the line of the first two) or a point; b maybe too.
    const int k = *rc::gen::inRange(-2, 3);
    a[2] = a[0] + double(k) * (a[1] - a[0]);
    if (*rc::gen::arbitrary<bool>()) a[1] = a[0], a[2] = a[0];
    if (*rc::gen::arbitrary<bool>()) b[2] = 0.5 * (b[0] + b[1]);
    check_pair(a, b);
  }));
}

}  // namespace
}  // namespace fdh
