// robust's integer stage (fast/src/ccd_robust_integer.cpp): the queries that defeat floating
// point, on small integer coordinates, decided exactly without the exact fallback; its verdicts
// and times equal the exact twin's, on hand-made cases and on the six hard families; it declines
// coordinates beyond 32 bits.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fdh/ccd/robust.hpp"
#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/gen/case_seed.hpp"
#include "fdh/gen/families.hpp"

namespace fdh {
namespace {

Query integer_case(const std::array<Vec3, 8>& x) {
  Query q;
  q.kind = QueryKind::VertexFace;
  q.x = x;
  return q;
}

// The triangle (0,0,0), (1,0,0), (0,1,0) still; the point moves in its plane from `from` to `to`.
Query moving_in_plane(const Vec3& from, const Vec3& to) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  return integer_case({from, a, b, c, to, a, b, c});
}

TEST(RobustCcdInteger, DecidesCoplanarMotionThatMisses) {
  const Query q = moving_in_plane({3, 3, 0}, {2, 2, 0});
  EXPECT_FALSE(exact::ccd_hit(q));
  EXPECT_EQ(robust_ccd_filter(q), Filtered::No);
  EXPECT_EQ(robust_ccd_stage(q), RobustStage::Integer);
}

// The point crosses the hypotenuse's line x + y = 1 at t = 1/3, inside the edge: the contact at
// an exact time that is no double, enclosed by the doubles on either side.
TEST(RobustCcdInteger, EnclosesAContactAtAFractionThatIsNoDouble) {
  const Query q = moving_in_plane({1, 1, 0}, {-0.5, -0.5, 0});
  ASSERT_TRUE(exact::ccd_hit(q));
  EXPECT_EQ(robust_ccd_stage(q), RobustStage::Integer);
  const Toi toi = robust_ccd_toi(q, kMinToiWidth, &exact::ccd_toi);
  ASSERT_TRUE(toi.hit);
  EXPECT_LT(toi.t_lo, 1.0 / 3 + 1e-15);
  EXPECT_LE(toi.t_hi - toi.t_lo, kMinToiWidth);
  EXPECT_LT(exact::compare_with_toi(q, toi.t_lo), 0);
  EXPECT_GT(exact::compare_with_toi(q, toi.t_hi), 0);
}

// Brochu et al.'s hourglass, missed: the triangle shrinks to the point (0,0,0) at t = 1/2 while
// the vertex passes 1 above it. f = -c (1 - 2t)^2: a double root, which no error bound isolates.
TEST(RobustCcdInteger, DecidesADoubleRootAtADyadicTime) {
  const Vec3 u{1, 0, 0}, v{0, 1, 0}, w{-1, -1, 0}, p{0, 0, 1};
  const Query q = integer_case({p, u, v, w, p, -1 * u, -1 * v, -1 * w});
  EXPECT_FALSE(exact::ccd_hit(q));
  EXPECT_EQ(robust_ccd_filter(q), Filtered::No);
  EXPECT_EQ(robust_ccd_stage(q), RobustStage::Integer);
}

// Coplanar throughout, the edge ab turning: the point p(t) = (2t, 1) enters the triangle through
// ab (the line y = t x) at t = 1/sqrt(2), an irrational root of 4t^2 - 2.
TEST(RobustCcdInteger, DecidesAContactAtAnIrrationalRootOfAQuadratic) {
  const Vec3 a{0, 0, 0}, c{2, -4, 0};
  const Query q =
      integer_case({Vec3{0, 1, 0}, a, Vec3{2, 0, 0}, c, Vec3{2, 1, 0}, a, Vec3{2, 2, 0}, c});
  ASSERT_TRUE(exact::ccd_hit(q));
  EXPECT_EQ(robust_ccd_filter(q), Filtered::Yes);
  EXPECT_EQ(robust_ccd_stage(q), RobustStage::Integer);
  const Toi toi = robust_ccd_toi(q, 0x1p-40, &exact::ccd_toi);
  EXPECT_TRUE(toi.hit);
  EXPECT_LE(toi.t_lo, 1 / std::sqrt(2.0));
  EXPECT_GE(toi.t_hi, 1 / std::sqrt(2.0) - 1e-15);
}

// 0.1 needs 2^56 beside 1: beyond 32 bits the stage declines, and a landing on an edge at the
// end goes to the exact test.
TEST(RobustCcdInteger, DeclinesCoordinatesBeyondItsWidth) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  const Query q = integer_case({Vec3{0.25, 0.25, 1}, a, b, c, Vec3{0.1, 0, 0}, a, b, c});
  EXPECT_EQ(robust_ccd_stage(q), RobustStage::Exact);
  EXPECT_TRUE(robust_ccd(q, &exact::ccd_hit));
}

// Every case of the six hard families: robust's verdict is exact's without the fallback (the
// fallback asked here fails the test), and its time of impact encloses exact's.
bool no_fallback(const Query&) {
  ADD_FAILURE() << "robust called its exact fallback";
  return false;
}

TEST(RobustCcdInteger, EqualsExactOnTheHardFamilies) {
  for (const char* name : {"hourglass", "two-crossings", "coplanar", "sliding-on-edge",
                           "parallel-edges", "degenerate-edge"}) {
    SCOPED_TRACE(name);
    const verify::Family* family = nullptr;
    for (const verify::Family& f : verify::all_families())
      if (f.name == name) family = &f;
    ASSERT_NE(family, nullptr);
    int left = 0;
    for (long i = 0; i < 300; ++i) {
      const Query q = verify::generate(*family, verify::case_seed(11, i)).query;
      const bool hit = exact::ccd_hit(q), to_exact = robust_ccd_stage(q) == RobustStage::Exact;
      left += to_exact;
      ASSERT_EQ(robust_ccd(q, to_exact ? &exact::ccd_hit : &no_fallback), hit) << "case " << i;
      const Toi toi = robust_ccd_toi(q, 0x1p-30, &exact::ccd_toi);
      ASSERT_EQ(toi.hit, hit) << "case " << i;
      if (!hit) continue;
      EXPECT_LE(exact::compare_with_toi(q, toi.t_lo), 0) << "case " << i;
      EXPECT_GE(exact::compare_with_toi(q, toi.t_hi), 0) << "case " << i;
    }
    EXPECT_LE(left, 3) << "queries left to the exact fallback";  // none at the seeds measured
  }
}

}  // namespace
}  // namespace fdh
