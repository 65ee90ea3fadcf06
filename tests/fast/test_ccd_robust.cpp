// The robust CCD filter at the ends of the step: a point that lands exactly in the plane of a
// triangle at t = 1 (or leaves it at t = 0) makes f zero there, a sign no error bound
// certifies. The filter settles it when the point is then certainly inside (yes) or certainly
// outside (no), and agrees with the exact test.
#include <gtest/gtest.h>

#include "fdh/ccd/robust.hpp"
#include "fdh/exact/ccd.hpp"

namespace fdh {
namespace {

// The point moves from (0.25, 0.25, 1), over the triangle (0,0,0), (1,0,0), (0,1,0), to
// (x, y, 0) in its plane; reversed in time, it starts there.
Query landing(double x, double y, bool reversed) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, above{0.25, 0.25, 1}, on{x, y, 0};
  Query q;
  q.x = {reversed ? on : above, a, b, c, reversed ? above : on, a, b, c};
  return q;
}

TEST(RobustCcdFilter, SettlesAContactOrItsAbsenceExactlyAtAnEnd) {
  for (const bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "leaving the plane at t = 0" : "landing in the plane at t = 1");
    const Query inside = landing(0.5, 0.25, reversed), outside = landing(2, 2, reversed);
    ASSERT_TRUE(exact::ccd_hit(inside));
    EXPECT_EQ(robust_ccd_filter(inside), Filtered::Yes);
    ASSERT_FALSE(exact::ccd_hit(outside));
    EXPECT_EQ(robust_ccd_filter(outside), Filtered::No);
  }
}

// Coplanar throughout (f = 0 on all of [0, 1], every point in the plane z = 0), starting inside
// the triangle: a contact at t = 0 although no coefficient of f has a sign.
TEST(RobustCcdFilter, SettlesCoplanarMotionThatStartsInside) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  Query q;
  q.x = {Vec3{0.25, 0.25, 0}, a, b, c, Vec3{2, 2, 0}, a, b, c};
  ASSERT_TRUE(exact::ccd_hit(q));
  EXPECT_EQ(robust_ccd_filter(q), Filtered::Yes);
  q.x[0] = {3, 3, 0};  // starting outside: the integer stage decides (small integers)
  EXPECT_FALSE(exact::ccd_hit(q));
  EXPECT_EQ(robust_ccd_filter(q), Filtered::No);
  EXPECT_EQ(robust_ccd_stage(q), RobustStage::Integer);
}

// On an edge at the end: a condition is zero there, which no interval shows; on these small
// dyadic coordinates the integer stage decides it (beyond them the exact test does:
// test_ccd_robust_integer.cpp).
TEST(RobustCcdFilter, SettlesATouchOnAnEdgeAtAnEndOnIntegers) {
  const Query on_edge = landing(0.5, 0, false);
  EXPECT_EQ(robust_ccd_filter(on_edge), Filtered::Yes);
  EXPECT_EQ(robust_ccd_stage(on_edge), RobustStage::Integer);
  EXPECT_TRUE(robust_ccd(on_edge, &exact::ccd_hit));
}

}  // namespace
}  // namespace fdh
