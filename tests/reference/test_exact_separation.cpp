// The exact minimum-separation CCD (exact::ccd_hit, ccd_toi, compare_with_toi and ccd with
// q.min_distance = δ > 0) on hand-made cases whose answers are known: distance exactly δ, δ
// moved by 2^-40, each closest feature, parallel edges, a dip at an irrational time, δ larger
// than the primitives, degenerate primitives, no motion; each checked also against CGAL's exact
// distance at the times involved (exact::compare_distance_at).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fdh/exact/ccd.hpp"
#include "fdh/exact/distance.hpp"

namespace fdh::exact {
namespace {

Query query(QueryKind kind, const Vec3 (&x)[8], double delta) {
  Query q;
  q.kind = kind;
  for (int i = 0; i < 8; ++i) q.x[i] = x[i];
  q.min_distance = delta;
  return q;
}

// The point moves from p0 to p1 past the still triangle (0,0,0), (1,0,0), (0,1,0).
Query point_past_triangle(Vec3 p0, Vec3 p1, double delta) {
  const Vec3 x[8] = {p0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, p1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  return query(QueryKind::VertexFace, x, delta);
}

// Edge a still from (-1,0,0) to (1,0,0); edge b from b0 to b1 moves by `shift` over the step.
Query edge_past_edge(Vec3 b0, Vec3 b1, Vec3 shift, double delta) {
  const Vec3 a0{-1, 0, 0}, a1{1, 0, 0};
  const Vec3 x[8] = {a0, a1, b0, b1, a0, a1, b0 + shift, b1 + shift};
  return query(QueryKind::EdgeEdge, x, delta);
}

// t* is exactly the double t: the verdict, compare_with_toi at t and its neighbours, ccd_toi's
// enclosure, the exact fraction, and the distance there by CGAL.
void expect_exact_time(const Query& q, double t) {
  ASSERT_TRUE(ccd_hit(q));
  EXPECT_EQ(compare_with_toi(q, t), 0);
  if (t > 0) {
    EXPECT_EQ(compare_with_toi(q, std::nextafter(t, 0.0)), -1);
  }
  if (t < 1) {
    EXPECT_EQ(compare_with_toi(q, std::nextafter(t, 1.0)), 1);
  }
  const Toi toi = ccd_toi(q, 0, 1, kMinToiWidth);
  ASSERT_TRUE(toi.hit);
  EXPECT_LE(toi.t_lo, t);
  EXPECT_GE(toi.t_hi, t);
  EXPECT_LE(compare_distance_at(q, t), 0);
  if (t > 0) {
    EXPECT_GT(compare_distance_at(q, std::nextafter(t, 0.0)), 0);
  }
  const CcdContact c = ccd(q);
  ASSERT_TRUE(c.hit);
  EXPECT_LE(c.time_lo_down, t);
  EXPECT_GE(c.time_hi_up, t);
}

// t* is not a double: it lies strictly between the two doubles that ccd_toi returns at the
// narrowest width, where CGAL finds the distance above and below δ.
void expect_time_between_doubles(const Query& q, double near) {
  const Toi toi = ccd_toi(q, 0, 1, kMinToiWidth);
  ASSERT_TRUE(toi.hit);
  EXPECT_LE(toi.t_hi - toi.t_lo, kMinToiWidth);
  EXPECT_NEAR(toi.t_lo, near, 1e-15);
  EXPECT_EQ(compare_with_toi(q, toi.t_lo), -1);
  EXPECT_EQ(compare_with_toi(q, toi.t_hi), 1);
  EXPECT_GT(compare_distance_at(q, toi.t_lo), 0);
  EXPECT_LT(compare_distance_at(q, toi.t_hi), 0);
}

TEST(ExactSeparation, FaceInteriorFallingPoint) {
  // Height 1 - 2t above the face's interior: within 1/2 from t = 1/4.
  expect_exact_time(point_past_triangle({0.25, 0.25, 1}, {0.25, 0.25, -1}, 0.5), 0.25);
}

TEST(ExactSeparation, DistanceExactlyDeltaCounts) {
  // Still, at distance exactly d: over the face, beside an edge, off a corner (3-4-5).
  const struct {
    Vec3 p;
    double d;
  } cases[] = {{{0.25, 0.25, 0.5}, 0.5}, {{0.5, -0.5, 0}, 0.5}, {{-0.375, -0.5, 0}, 0.625}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.d);
    const Query q = point_past_triangle(c.p, c.p, c.d);
    EXPECT_EQ(compare_distance_at(q, 0), 0);
    expect_exact_time(q, 0);
    EXPECT_TRUE(ccd_hit(point_past_triangle(c.p, c.p, c.d * (1 + 0x1p-40))));
    EXPECT_FALSE(ccd_hit(point_past_triangle(c.p, c.p, c.d * (1 - 0x1p-40))));
  }
}

TEST(ExactSeparation, VertexClosestAtARationalTime) {
  // |p(t)| = 5 (1 - 3t/4) in the corner (0,0,0)'s region: within 2 from t = 4/5.
  const Query q = point_past_triangle({-3, -4, 0}, {-0.75, -1, 0}, 2);
  expect_time_between_doubles(q, 0.8);
}

TEST(ExactSeparation, EdgeClosestTouchesOnce) {
  // Passing below the edge (0,0,0)-(1,0,0): distance sqrt(4 + (1 - 2t)^2), 2 at t = 1/2 only.
  const Vec3 p0{0.5, -2, 1}, p1{0.5, -2, -1};
  expect_exact_time(point_past_triangle(p0, p1, 2), 0.5);
  EXPECT_FALSE(ccd_hit(point_past_triangle(p0, p1, 2 * (1 - 0x1p-40))));
  const Query wider = point_past_triangle(p0, p1, 2 * (1 + 0x1p-40));
  EXPECT_EQ(compare_with_toi(wider, 0.5), 1);  // a little earlier
  EXPECT_EQ(compare_with_toi(wider, 0.4999), -1);
}

TEST(ExactSeparation, VertexSlidingAtHeightDelta) {
  const double h = 0x1p-20;
  // Sliding over the face at height exactly δ throughout: t* = 0.
  expect_exact_time(point_past_triangle({0.125, 0.25, h}, {0.5, 0.25, h}, h), 0);
  // Coming from beside the edge x = 0 at height δ: within δ from the edge on, at t = 1/4.
  const Vec3 p0{-0.5, 0.25, h}, p1{1.5, 0.25, h};
  expect_exact_time(point_past_triangle(p0, p1, h), 0.25);
  EXPECT_FALSE(ccd_hit(point_past_triangle(p0, p1, h * (1 - 0x1p-40))));
}

TEST(ExactSeparation, ADipAtAnIrrationalTime) {
  // In the corner's region, |p(t)|^2 = 2 + (2 - 4t)^2 <= 4 for t in [(2 - sqrt 2)/4, ...].
  const Query q = point_past_triangle({-1, -1, 2}, {-1, -1, -2}, 2);
  expect_time_between_doubles(q, (2 - std::sqrt(2.0)) / 4);
  EXPECT_EQ(compare_with_toi(q, 0.5), 1);
  EXPECT_EQ(compare_with_toi(q, 0.1), -1);
}

TEST(ExactSeparation, ParallelEdgesAtDistanceDelta) {
  // Parallel throughout at distance 1, sliding along: within 1 at the start, not within less.
  const Vec3 b0{0.5, 1, 0}, b1{1.5, 1, 0}, slide{-1, 0, 0};
  expect_exact_time(edge_past_edge(b0, b1, slide, 1), 0);
  EXPECT_FALSE(ccd_hit(edge_past_edge(b0, b1, slide, 1 - 0x1p-40)));
  // Parallel, approaching: y = 2 - 3t/2 reaches 1 at t = 2/3.
  expect_time_between_doubles(edge_past_edge({0, 2, 0}, {1, 2, 0}, {0, -1.5, 0}, 1), 2.0 / 3);
  // Parallel, past the end: the distance is an end's, sqrt(1 + 1/4) > 1 throughout.
  EXPECT_FALSE(ccd_hit(edge_past_edge({1.5, 1, 0}, {2.5, 1, 0}, {0, 0, 0}, 1)));
}

TEST(ExactSeparation, CrossingEdgesInteriorClosest) {
  // b along y passes over a along x at height 2 - 4t: within 1/2 from t = 3/8.
  expect_exact_time(edge_past_edge({0, -1, 2}, {0, 1, 2}, {0, 0, -4}, 0.5), 0.375);
  // Beyond a's end: the closest points are a's end and b's interior.
  // 1 + (2 - 4t)^2 <= (5/4)^2 from t = 5/16.
  expect_exact_time(edge_past_edge({2, -1, 2}, {2, 1, 2}, {0, 0, -4}, 1.25), 0.3125);
}

TEST(ExactSeparation, DeltaLargerThanThePrimitives) {
  const double s = 0x1p-20;  // a tiny triangle and edge, 1 away, δ = 10
  const Vec3 x[8] = {{0, 0, 1}, {0, 0, 0}, {s, 0, 0}, {0, s, 0},
                     {0, 0, 1}, {0, 0, 0}, {s, 0, 0}, {0, s, 0}};
  expect_exact_time(query(QueryKind::VertexFace, x, 10), 0);
  expect_exact_time(query(QueryKind::EdgeEdge, x, 10), 0);
  EXPECT_FALSE(ccd_hit(query(QueryKind::VertexFace, x, 0.5)));
}

TEST(ExactSeparation, DegenerateTriangleAndSegment) {
  // A triangle flattened to the segment (0,0,0)-(2,0,0), the point at height 1/2 over its middle.
  const Vec3 p{1, 0, 0.5}, a{0, 0, 0}, b{2, 0, 0}, c{1, 0, 0};
  const Vec3 x[8] = {p, a, b, c, p, a, b, c};
  expect_exact_time(query(QueryKind::VertexFace, x, 0.5), 0);
  EXPECT_FALSE(ccd_hit(query(QueryKind::VertexFace, x, 0.25)));
  // A triangle shrunk to a point, and a zero-length edge: distances between points.
  const Vec3 y[8] = {p, a, a, a, p, a, a, a};
  EXPECT_FALSE(ccd_hit(query(QueryKind::VertexFace, y, 1)));  // |p| = sqrt(5)/2 > 1
  expect_exact_time(query(QueryKind::VertexFace, y, 1.25), 0);
  const Vec3 z[8] = {a, a, p, c, a, a, p, c};  // edge a is the point 0; b from p to (1,0,0)
  expect_exact_time(query(QueryKind::EdgeEdge, z, 1), 0);
  EXPECT_FALSE(ccd_hit(query(QueryKind::EdgeEdge, z, 1 - 0x1p-40)));
}

TEST(ExactSeparation, ZeroMotion) {
  const Vec3 p{0.25, 0.25, 1};
  expect_exact_time(point_past_triangle(p, p, 1), 0);
  EXPECT_FALSE(ccd_hit(point_past_triangle(p, p, 0.5)));
  EXPECT_THROW(compare_with_toi(point_past_triangle(p, p, 0.5), 0.5), std::invalid_argument);
}

TEST(ExactSeparation, TheWindowIsSearchedOnly) {
  const Query q = point_past_triangle({0.25, 0.25, 1}, {0.25, 0.25, -1}, 0.5);  // t* = 1/4
  EXPECT_FALSE(ccd_toi(q, 0, 0.125, 0x1p-30).hit);
  const Toi toi = ccd_toi(q, 0.125, 0.5, 0x1p-30);
  ASSERT_TRUE(toi.hit);
  EXPECT_LE(toi.t_lo, 0.25);
  EXPECT_GE(toi.t_hi, 0.25);
  EXPECT_TRUE(ccd_toi(q, 0.5, 0.75, 0x1p-30).hit);  // within δ throughout [1/4, 3/4]
  EXPECT_FALSE(ccd_toi(q, 0.875, 1, 0x1p-30).hit);
}

TEST(ExactSeparation, ExtremeDistancesStayExact) {
  // The falling point meets the face at t = 1/2: within the smallest subnormal δ a hair before,
  // within 2^-1000 a little before that; within 1e300 (far beyond the scene) from the start.
  const Vec3 p0{0.25, 0.25, 1}, p1{0.25, 0.25, -1};
  expect_exact_time(point_past_triangle(p0, p1, 0x1p-40), 0.5 - 0x1p-41);  // |1 - 2t| <= δ
  for (const double d : {0x1p-1074, 0x1p-1000}) {  // t* = 1/2 - δ/2: no double but 1/2 near
    SCOPED_TRACE(d);
    const Query q = point_past_triangle(p0, p1, d);
    const double below = std::nextafter(0.5, 0.0);
    EXPECT_EQ(compare_with_toi(q, 0.5), 1);
    EXPECT_EQ(compare_with_toi(q, below), -1);
    EXPECT_LT(compare_distance_at(q, 0.5), 0);
    EXPECT_GT(compare_distance_at(q, below), 0);
    const Toi toi = ccd_toi(q, 0, 1, kMinToiWidth);
    EXPECT_EQ(toi.t_lo, below);
    EXPECT_EQ(toi.t_hi, 0.5);
  }
  expect_exact_time(point_past_triangle(p0, p1, 1e300), 0);
  const Vec3 far{1e20, -3e19, 7e18};
  EXPECT_FALSE(ccd_hit(point_past_triangle(far, far, 1e19)));
  EXPECT_TRUE(ccd_hit(point_past_triangle(far, far, 1.1e20)));
}

TEST(ExactSeparation, BadDistancesAreRefused) {
  Query q = point_past_triangle({0, 0, 1}, {0, 0, 1}, -1);
  EXPECT_THROW(ccd_hit(q), std::invalid_argument);
  q.min_distance = INFINITY;
  EXPECT_THROW(ccd_hit(q), std::invalid_argument);
  q.min_distance = NAN;
  EXPECT_THROW(ccd_toi(q, 0, 1, 0x1p-30), std::invalid_argument);
}

}  // namespace
}  // namespace fdh::exact
