// compare_with_toi decides t < t*, t = t*, t > t* exactly, next to the contact time down to the
// neighbouring doubles: a dyadic t*, a rational one and an irrational one; and ccd_toi searches
// only the window it is given.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fdh/exact/ccd.hpp"

namespace fdh::exact {
namespace {

Query toi_falling_point(double stop_z, double tilt) {
  Query q;
  q.kind = QueryKind::VertexFace;
  const Vec3 x[8] = {{0.2, 0.2, 1},      {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                     {0.2, 0.2, stop_z}, {0, 0, 0}, {1, 0, 0}, {0, 1, tilt}};
  for (int i = 0; i < 8; ++i) q.x[i] = x[i];
  return q;
}

TEST(CompareWithToi, ADyadicContactTimeIsHitExactly) {
  const Query q = toi_falling_point(-1, 0);  // t* = 1/2
  EXPECT_EQ(compare_with_toi(q, 0.5), 0);
  EXPECT_EQ(compare_with_toi(q, std::nextafter(0.5, 0.0)), -1);
  EXPECT_EQ(compare_with_toi(q, std::nextafter(0.5, 1.0)), 1);
  EXPECT_EQ(compare_with_toi(q, 0), -1);
  EXPECT_EQ(compare_with_toi(q, 1), 1);
}

TEST(CompareWithToi, ARationalContactTimeLiesBetweenTwoNeighbouringDoubles) {
  const Query q = toi_falling_point(-1, 1);  // t* = 1 / (2 + fl(0.2)), about 5/11
  const Toi toi = ccd_toi(q, 0, 1, kMinToiWidth);
  ASSERT_TRUE(toi.hit);
  EXPECT_LE(toi.t_hi - toi.t_lo, kMinToiWidth);
  EXPECT_EQ(compare_with_toi(q, toi.t_lo), -1);  // no double equals t*
  EXPECT_EQ(compare_with_toi(q, toi.t_hi), 1);
  EXPECT_NEAR(toi.t_lo, 5.0 / 11, 1e-15);
  // A window of one instant next to t* (inside the root's first isolating interval): no contact.
  EXPECT_FALSE(ccd(q, {toi.t_lo, toi.t_lo, 0}).hit);
  EXPECT_FALSE(ccd(q, {toi.t_hi, toi.t_hi, 0}).hit);
  EXPECT_FALSE(ccd(q, {0.4375, 0.4375, 0}).hit);
  EXPECT_TRUE(ccd(q, {0.4375, 0.5, 0}).hit);
}

TEST(CompareWithToi, ByTheWindowOnly) {
  const Query q = toi_falling_point(-1, 0);
  EXPECT_FALSE(ccd_toi(q, 0, 0.25, 0x1p-30).hit);  // before the contact: nothing there
  const Toi toi = ccd_toi(q, 0.25, 0.75, 0x1p-30);
  ASSERT_TRUE(toi.hit);
  EXPECT_LE(toi.t_lo, 0.5);
  EXPECT_GE(toi.t_hi, 0.5);
}

TEST(CompareWithToi, AQueryWithoutContactIsRefused) {
  EXPECT_THROW(compare_with_toi(toi_falling_point(0.5, 0), 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace fdh::exact
