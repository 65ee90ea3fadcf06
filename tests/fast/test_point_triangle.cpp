// Hand-computed cases for every point–triangle method; the exact test's kinds and times.
#include <gtest/gtest.h>

#include <limits>

#include "fdh/exact/point_triangle.hpp"
#include "fdh/point_triangle/linear_system.hpp"
#include "fdh/point_triangle/paper.hpp"
#include "fdh/point_triangle/robust.hpp"

namespace fdh {
namespace {

const Vec3 D{0, 0, 0}, E{1, 0, 0}, F{0, 1, 0};

struct Case {
  const char* what;
  Vec3 b0, b1, d, e, f;
  bool hit;
  exact::ContactKind kind;
  const char* time;
};

const Case kCases[] = {
    {"straight through the face",
     {0.25, 0.25, 1},
     {0.25, 0.25, -1},
     D,
     E,
     F,
     true,
     exact::ContactKind::Face,
     "1/2"},
    {"stops short",
     {0.25, 0.25, 1},
     {0.25, 0.25, 0.5},
     D,
     E,
     F,
     false,
     exact::ContactKind::None,
     ""},
    {"lands on the face at t = 1",
     {0.25, 0.25, 1},
     {0.25, 0.25, 0},
     D,
     E,
     F,
     true,
     exact::ContactKind::Face,
     "1"},
    {"through an edge", {0.5, 0, 1}, {0.5, 0, -1}, D, E, F, true, exact::ContactKind::Edge, "1/2"},
    {"through a vertex", {0, 0, 1}, {0, 0, -3}, D, E, F, true, exact::ContactKind::Vertex, "1/4"},
    {"crosses the plane outside",
     {2, 2, 1},
     {2, 2, -1},
     D,
     E,
     F,
     false,
     exact::ContactKind::None,
     ""},
    {"angled through the face",
     {0, 0, 1},
     {0.5, 0.5, -1},
     D,
     E,
     F,
     true,
     exact::ContactKind::Face,
     "1/2"},
    {"in the plane, across",
     {-1, 0.25, 0},
     {2, 0.25, 0},
     D,
     E,
     F,
     true,
     exact::ContactKind::InPlane,
     "1/3"},
    {"in the plane, beside", {-1, -1, 0}, {2, -1, 0}, D, E, F, false, exact::ContactKind::None, ""},
    {"no motion, on the face",
     {0.25, 0.25, 0},
     {0.25, 0.25, 0},
     D,
     E,
     F,
     true,
     exact::ContactKind::InPlane,
     "0"},
    {"no motion, above",
     {0.25, 0.25, 1},
     {0.25, 0.25, 1},
     D,
     E,
     F,
     false,
     exact::ContactKind::None,
     ""},
    {"zero-area triangle, its middle",
     {1.5, 0, 1},
     {1.5, 0, -1},
     {0, 0, 0},
     {1, 0, 0},
     {2, 0, 0},
     true,
     exact::ContactKind::Edge,
     "1/2"},
    {"zero-area triangle, its end",
     {2, 0, 1},
     {2, 0, -1},
     {0, 0, 0},
     {1, 0, 0},
     {2, 0, 0},
     true,
     exact::ContactKind::Vertex,
     "1/2"},
    {"zero-area triangle, beyond",
     {3, 0, 1},
     {3, 0, -1},
     {0, 0, 0},
     {1, 0, 0},
     {2, 0, 0},
     false,
     exact::ContactKind::None,
     ""},
    {"zero-area triangle, along it",
     {-1, 0, 0},
     {0.5, 0, 0},
     {0, 0, 0},
     {1, 0, 0},
     {2, 0, 0},
     true,
     exact::ContactKind::Vertex,
     "2/3"},
    {"point triangle, hit",
     {0, 0, 0},
     {2, 2, 2},
     {1, 1, 1},
     {1, 1, 1},
     {1, 1, 1},
     true,
     exact::ContactKind::Vertex,
     "1/2"},
    {"point triangle, miss",
     {0, 0, 0},
     {2, 2, 3},
     {1, 1, 1},
     {1, 1, 1},
     {1, 1, 1},
     false,
     exact::ContactKind::None,
     ""},
};

TEST(ExactPointTriangle, HandComputedCases) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.what);
    const exact::PointTriangleContact r = exact::point_triangle(c.b0, c.b1, c.d, c.e, c.f);
    EXPECT_EQ(r.hit, c.hit);
    EXPECT_EQ(r.kind, c.kind) << exact::to_string(r.kind);
    EXPECT_EQ(r.time, c.time);
    EXPECT_EQ(exact::point_triangle_hit(c.b0, c.b1, c.d, c.e, c.f), c.hit);
  }
}

TEST(RobustPointTriangle, EqualsExactOnHandCases) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.what);
    EXPECT_EQ(robust_point_triangle(c.b0, c.b1, c.d, c.e, c.f, &exact::point_triangle_hit), c.hit);
  }
}

TEST(RobustPointTriangle, FilterDecidesGenericCasesAlone) {
  EXPECT_EQ(robust_point_triangle_filter({0.25, 0.25, 1}, {0.25, 0.25, -1}, D, E, F),
            Filtered::Yes);
  EXPECT_EQ(robust_point_triangle_filter({0.25, 0.25, 1}, {0.25, 0.25, 0.5}, D, E, F),
            Filtered::No);
  EXPECT_EQ(robust_point_triangle_filter({2, 2, 1}, {2, 2, -1}, D, E, F), Filtered::No);
  // Touching needs a zero sign, which a filter never certifies.
  EXPECT_EQ(robust_point_triangle_filter({0.5, 0, 1}, {0.5, 0, -1}, D, E, F), Filtered::Uncertain);
}

// The error bounds hold only inside the filter's range, and a NaN has no sign: uncertain, in
// either lane of the side-by-side evaluation (e and B' in one, f and D in the other).
TEST(RobustPointTriangle, FilterIsUncertainOutsideItsRangeAndOnNaN) {
  const Vec3 b0{0.25, 0.25, 1}, b1{0.25, 0.25, -1};
  ASSERT_EQ(robust_point_triangle_filter(b0, b1, D, E, F), Filtered::Yes);
  for (const double scale : {0x1p400, 0x1p-400}) {  // the same hit, stretched in x and y
    const auto s = [scale](const Vec3& v) { return Vec3{v.x * scale, v.y * scale, v.z}; };
    EXPECT_EQ(robust_point_triangle_filter(s(b0), s(b1), s(D), s(E), s(F)), Filtered::Uncertain);
  }
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), 0x1p400})
    for (int i = 0; i < 5; ++i) {
      Vec3 v[5] = {b0, b1, D, E, F};
      v[i].y = bad;
      EXPECT_EQ(robust_point_triangle_filter(v[0], v[1], v[2], v[3], v[4]), Filtered::Uncertain)
          << "point " << i << ", y = " << bad;
    }
}

// A long motion just above a triangle: the x differences reach 2^28, the others stay near 1,
// so stage 1's one bound (the largest coordinates by axis) covers orient3d(D, E, F, B) of
// 2^-29 no more; stage 2's bound from that determinant's own permanent does, and the crossing
// at (1/4, 0, 0) is certain.
TEST(RobustPointTriangle, SecondStageDecidesWhereCoordinatesDifferInSize) {
  const Vec3 d{-1, -1, 0}, e{1, -1, 0}, f{0, 1, 0}, b0{0, 0, 0x1p-30}, b1{0x1p28, 0, -1};
  ASSERT_TRUE(exact::point_triangle_hit(b0, b1, d, e, f));
  EXPECT_EQ(robust_point_triangle_quick(b0, b1, d, e, f), Filtered::Uncertain);
  EXPECT_EQ(robust_point_triangle_tight(b0, b1, d, e, f), Filtered::Yes);
  EXPECT_EQ(robust_point_triangle_filter(b0, b1, d, e, f), Filtered::Yes);
}

// The paper's own figures. Fig. 3: B falls along the normal through the triangle.
TEST(PaperMethods, Fig3ParallelCrossing) {
  const Vec3 b0{0.25, 0.25, 1}, b1{0.25, 0.25, -1};
  EXPECT_FALSE(paper_literal(b0, b1, D, E, F));  // N1 != 0 and N3 = |NB'|^2 = 1 > 0: a miss
  EXPECT_TRUE(paper_intended(b0, b1, D, E, F));  // N2 = BB'·B'N = -2 <= 0
  EXPECT_TRUE(linear_system(b0, b1, D, E, F));
}

// Fig. 4: at an angle, B' below the plane.
TEST(PaperMethods, Fig4AngledCrossing) {
  const Vec3 b0{0, 0, 1}, b1{0.5, 0.5, -1};
  EXPECT_FALSE(paper_literal(b0, b1, D, E, F));
  EXPECT_TRUE(paper_intended(b0, b1, D, E, F));  // N3 = NB'·NB = -1 <= 0
  EXPECT_TRUE(linear_system(b0, b1, D, E, F));
}

TEST(PaperMethods, NoneChecksTheTriangleButTheLinearSystem) {
  const Vec3 b0{5, 5, 1}, b1{5, 5, -1};  // crosses the plane far outside DEF
  EXPECT_TRUE(paper_intended(b0, b1, D, E, F));
  EXPECT_FALSE(linear_system(b0, b1, D, E, F));
}

TEST(PaperMethods, LiteralHitsWheneverThereIsNoMotion) {
  const Vec3 b{7, 7, 7};  // N1 = 0, then N2 = 0·B'D = 0 <= 0
  EXPECT_TRUE(paper_literal(b, b, D, E, F));
}

TEST(LinearSystem, SingularMotionInThePlaneIsANo) {
  EXPECT_FALSE(linear_system({-1, 0.25, 0}, {2, 0.25, 0}, D, E, F));
}

}  // namespace
}  // namespace fdh
