// `robust` within the minimum separation δ (q.min_distance > 0) on its own, before its exact
// twin: hand-made queries whose distance is known, where the filter must decide (and rightly),
// and random ones where each certain answer must agree with a brute-force look at the distance
// in long double: No, the distance sampled densely (and refined around its least sample) stays
// > δ; Yes, it comes within δ by the time the filter names, and not before the time it
// names as free. The float baseline
// (float_cubic at δ > 0) on the queries it should get right.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "brute_distance.hpp"
#include "fdh/ccd/float_cubic.hpp"
#include "fdh/ccd/robust.hpp"
#include "fdh/ccd/toi.hpp"

namespace fdh {
namespace {

using brute::distance_at;
using brute::L;
using brute::least_distance;

Query make(QueryKind kind, const Vec3 (&x)[8], double delta) {
  Query q;
  q.kind = kind;
  for (int i = 0; i < 8; ++i) q.x[i] = x[i];
  q.min_distance = delta;
  return q;
}

// The point slides at height h over the still unit triangle z = 0, from above its interior to
// past its hypotenuse: the distance is h while inside.
Query sliding_point(double h, double delta) {
  return make(
      QueryKind::VertexFace,
      {{0.1, 0.1, h}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, h}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      delta);
}
// Two parallel edges at distance d: the x axis's [0, 1] and the same at y = d, drifting in x.
Query parallel_edges(double d, double delta) {
  return make(QueryKind::EdgeEdge,
              {{0, 0, 0},
               {1, 0, 0},
               {0.5, d, 0},
               {1.5, d, 0},
               {0, 0, 0},
               {1, 0, 0},
               {-0.5, d, 0},
               {0.5, d, 0}},
              delta);
}
// The point falls past the triangle's corner (1, 0, 0) outside it, at least `gap` from it.
Query passing_corner(double gap, double delta) {
  return make(QueryKind::VertexFace,
              {{1 + gap, 0, 1},
               {0, 0, 0},
               {1, 0, 0},
               {0, 1, 0},
               {1 + gap, 0, -1},
               {0, 0, 0},
               {1, 0, 0},
               {0, 1, 0}},
              delta);
}

TEST(CcdRobustDelta, DecidesClearQueriesRightly) {
  for (const double h : {0.5, 1e-3, 1e-6}) {
    EXPECT_EQ(robust_ccd_filter(sliding_point(h, 1.01 * h)), Filtered::Yes) << h;
    EXPECT_EQ(robust_ccd_filter(sliding_point(h, 0.99 * h)), Filtered::No) << h;
    EXPECT_EQ(robust_ccd_filter(parallel_edges(h, 1.01 * h)), Filtered::Yes) << h;
    EXPECT_EQ(robust_ccd_filter(parallel_edges(h, 0.99 * h)), Filtered::No) << h;
    EXPECT_EQ(robust_ccd_filter(passing_corner(h, 1.01 * h)), Filtered::Yes) << h;
    EXPECT_EQ(robust_ccd_filter(passing_corner(h, 0.99 * h)), Filtered::No) << h;
  }
}

TEST(CcdRobustDelta, ExactlyAtTheDistanceIsLeftToTheExactTest) {
  // The point passes exactly δ = 1/2 from the corner: no floating-point margin either way.
  EXPECT_EQ(robust_ccd_filter(passing_corner(0.5, 0.5)), Filtered::Uncertain);
  EXPECT_EQ(robust_ccd(passing_corner(0.5, 0.5), [](const Query&) { return true; }), true);
}

TEST(CcdRobustDelta, ZeroDeltaIsTodaysContact) {
  // A contact at t = 1/2; at δ = 0 the same verdict as the contact filter, and within δ too.
  Query q = sliding_point(0, 0);
  q.x[0].z = 1, q.x[4] = {0.1, 0.1, -1};
  EXPECT_EQ(robust_ccd_filter(q), Filtered::Yes);
  q.min_distance = 1e-6;
  EXPECT_EQ(robust_ccd_filter(q), Filtered::Yes);
}

// The falling point reaches height δ at t = 1/2 - δ/2 (a dyadic δ: exact), its enclosure found
// by the filter alone, and never late.
TEST(CcdRobustDelta, EnclosesTheFirstTimeWithinDelta) {
  for (const double delta : {0x1p-4, 0x1p-20}) {
    Query q = sliding_point(0, delta);
    q.x[0].z = 1, q.x[4] = {0.1, 0.1, -1};
    const double t_star = 0.5 - delta / 2;
    for (const double w : {0x1p-30, 0x1p-40}) {
      const Toi toi = robust_ccd_toi(q, w, [](const Query&, double, double, double) {
        ADD_FAILURE() << "the exact fallback was not needed";
        return Toi{};
      });
      ASSERT_TRUE(toi.hit);
      EXPECT_LE(toi.t_lo, t_star);
      EXPECT_GE(toi.t_hi, t_star);
      EXPECT_LE(toi.t_hi - toi.t_lo, w);
      EXPECT_GT(toi.t_lo, 0);
    }
  }
}

TEST(CcdRobustDelta, FloatBaselineAnswersClearQueries) {
  for (const double h : {0.5, 1e-3}) {
    EXPECT_TRUE(float_cubic(sliding_point(h, 1.01 * h))) << h;
    EXPECT_FALSE(float_cubic(sliding_point(h, 0.99 * h))) << h;
    EXPECT_TRUE(float_cubic(parallel_edges(h, 1.01 * h))) << h;
    EXPECT_FALSE(float_cubic(parallel_edges(h, 0.99 * h))) << h;
    EXPECT_TRUE(float_cubic(passing_corner(h, 1.01 * h))) << h;
    EXPECT_FALSE(float_cubic(passing_corner(h, 0.99 * h))) << h;
  }
  Query q = sliding_point(0, 0x1p-4);
  q.x[0].z = 1, q.x[4] = {0.1, 0.1, -1};
  const Toi toi = float_cubic_toi(q);
  ASSERT_TRUE(toi.hit);
  EXPECT_NEAR(toi.t_lo, 0.5 - 0x1p-5, 1e-12);
}

// A random query in [-1, 1]^3 (coordinates on a grid of 10^-6, so that parallels and shared
// points occur), and a δ within 1% of its least distance over the step or of its distance at a
// random time (close calls both ways), or a plain random δ.
Query random_delta_query() {
  Query q;
  q.kind = *rc::gen::element(QueryKind::VertexFace, QueryKind::EdgeEdge);
  const int grid = *rc::gen::element(1, 4, 1000000);
  for (Vec3& v : q.x) {
    const auto c = [grid] { return double(*rc::gen::inRange(-grid, grid + 1)) / grid; };
    v = {c(), c(), c()};
  }
  const double scale = 1 + *rc::gen::inRange(-1000, 1001) * 1e-5;
  switch (*rc::gen::inRange(0, 3)) {
    case 0:
      q.min_distance = double(least_distance(q, 1)) * scale;
      break;
    case 1:
      q.min_distance = double(distance_at(q, *rc::gen::inRange(0, 1025) / 1024.0)) * scale;
      break;
    default:
      q.min_distance = *rc::gen::inRange(1, 1000001) * 1e-6;
  }
  RC_PRE(q.min_distance > 0);
  return q;
}

TEST(CcdRobustDelta, CertainAnswersAgreeWithTheDistance) {
  EXPECT_TRUE(rc::check("robust-within-delta-sound", [] {
    const Query q = random_delta_query();
    const FilteredToi f = robust_ccd_toi_filter(q, 0x1p-30);
    RC_ASSERT(f.verdict == robust_ccd_filter(q));
    const L delta = q.min_distance;
    RC_LOG() << std::setprecision(17) << (q.kind == QueryKind::VertexFace ? "vf" : "ee")
             << " delta " << q.min_distance << " verdict " << int(f.verdict) << " t0 " << f.t0
             << " t1 " << f.t1 << "\n";
    for (const Vec3& v : q.x)
      RC_LOG() << std::setprecision(17) << v.x << " " << v.y << " " << v.z << "\n";
    // The brute force resolves distances to about 1e-18 here (coordinates near 1, long double),
    // and to 1e-15 at a crossing (the refinement's last bracket): the slack of each check.
    if (f.verdict == Filtered::No) RC_ASSERT(least_distance(q, 1) > delta - 1e-18L);
    if (f.verdict == Filtered::Yes) {
      // Within δ by t1: at t1 itself, where the filter certified it, or before.
      RC_ASSERT(std::min(distance_at(q, f.t1), least_distance(q, f.t1)) <= delta + 1e-15L);
      if (f.t0 > 0) RC_ASSERT(least_distance(q, f.t0) > delta - 1e-18L);
      if (f.enclosed) RC_ASSERT(f.t1 - f.t0 <= 0x1p-30 && (f.t0 > 0 || f.t1 == 0));
    }
    RC_TAG(f.verdict == Filtered::Yes ? "yes" : f.verdict == Filtered::No ? "no" : "uncertain");
  }));
}

}  // namespace
}  // namespace fdh
