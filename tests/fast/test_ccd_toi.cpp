// robust_ccd_toi and float_cubic_toi on queries whose contact time is known: a dyadic time, a
// rational one that no double equals, an irrational one, a contact at the very start, none.
// Each enclosure is checked exactly by compare_with_toi (reference/), and the filter is seen to
// narrow its own root at both widths without the exact fallback.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"

namespace fdh {
namespace {

// A vertex-face query: the point p0 -> p1 against the triangle a0 b0 c0 -> a1 b1 c1.
Query toi_vertex_face(Vec3 p0, Vec3 a0, Vec3 b0, Vec3 c0, Vec3 p1, Vec3 a1, Vec3 b1, Vec3 c1) {
  Query q;
  q.kind = QueryKind::VertexFace;
  const Vec3 x[8] = {p0, a0, b0, c0, p1, a1, b1, c1};
  for (int i = 0; i < 8; ++i) q.x[i] = x[i];
  return q;
}

// The point falls through the fixed unit triangle z = 0 at t = 1/2.
Query toi_dyadic_contact() {
  return toi_vertex_face({0.2, 0.2, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -1}, {0, 0, 0},
                         {1, 0, 0}, {0, 1, 0});
}
// The triangle tilts (c rises to z = 1) while the point falls: 1 - 2t = 0.2 t, t = 5/11 (with
// 0.2's rounding: a rational that no double equals).
Query toi_rational_contact() {
  return toi_vertex_face({0.2, 0.2, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -1}, {0, 0, 0},
                         {1, 0, 0}, {0, 1, 1});
}
// Both b and c rise while the point also slides in x: 1 - 2t = 0.5 t^2 + 0.4 t, an irrational
// root (about 0.3857).
Query toi_irrational_contact() {
  return toi_vertex_face({0.2, 0.2, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.7, 0.2, -1}, {0, 0, 0},
                         {1, 0, 1}, {0, 1, 1});
}

int toi_fallbacks = 0;
Toi toi_counting_fallback(const Query& q, double t0, double t1, double width) {
  ++toi_fallbacks;
  return exact::ccd_toi(q, t0, t1, width);
}

void expect_toi_encloses(const Query& q, const Toi& toi, double width) {
  ASSERT_TRUE(toi.hit);
  EXPECT_LE(0, toi.t_lo);
  EXPECT_LE(toi.t_hi, 1);
  EXPECT_LE(toi.t_hi - toi.t_lo, width);
  EXPECT_LE(exact::compare_with_toi(q, toi.t_lo), 0);  // never late
  EXPECT_GE(exact::compare_with_toi(q, toi.t_hi), 0);
}

TEST(CcdToi, RobustNarrowsItsOwnRootAtBothWidths) {
  for (const Query& q : {toi_dyadic_contact(), toi_rational_contact(), toi_irrational_contact()})
    for (const double w : {0x1p-30, 0x1p-50}) {
      toi_fallbacks = 0;
      expect_toi_encloses(q, robust_ccd_toi(q, w, toi_counting_fallback), w);
      EXPECT_EQ(toi_fallbacks, 0) << w;
    }
}

TEST(CcdToi, TheExactFallbackEnclosesTooFromAnyWindowBeforeTheContact) {
  for (const Query& q : {toi_dyadic_contact(), toi_rational_contact(), toi_irrational_contact()})
    for (const double w : {0x1p-30, 0x1p-50, kMinToiWidth}) {
      expect_toi_encloses(q, exact::ccd_toi(q, 0, 1, w), w);
      expect_toi_encloses(q, exact::ccd_toi(q, 0.25, 1, w), w);
    }
}

TEST(CcdToi, NoContactIsTheWholeStep) {
  Query q = toi_dyadic_contact();
  q.x[4].z = 0.5;  // the point stops above the triangle
  const Toi toi = robust_ccd_toi(q, kDefaultToiWidth, exact::ccd_toi);
  EXPECT_FALSE(toi.hit);
  EXPECT_EQ(toi.t_lo, 1);
  EXPECT_EQ(toi.t_hi, 1);
  EXPECT_FALSE(float_cubic_toi(q).hit);
}

TEST(CcdToi, ZeroOnlyForAContactAtTheStart) {
  Query q = toi_dyadic_contact();
  q.x[0].z = 0;  // in the triangle at t = 0
  const Toi toi = robust_ccd_toi(q, kDefaultToiWidth, exact::ccd_toi);
  ASSERT_TRUE(toi.hit);
  EXPECT_EQ(toi.t_lo, 0);
  EXPECT_EQ(exact::compare_with_toi(q, 0), 0);
  // Just above at the start: t* > 0, and so is t_lo.
  q.x[0].z = 0x1p-40;
  const Toi later = robust_ccd_toi(q, kDefaultToiWidth, exact::ccd_toi);
  ASSERT_TRUE(later.hit);
  EXPECT_GT(later.t_lo, 0);
  expect_toi_encloses(q, later, kDefaultToiWidth);
}

TEST(CcdToi, FloatCubicReturnsItsRoot) {
  const Toi toi = float_cubic_toi(toi_dyadic_contact());
  ASSERT_TRUE(toi.hit);
  EXPECT_NEAR(toi.t_lo, 0.5, 1e-15);
  EXPECT_EQ(toi.t_hi, toi.t_lo);
  const Toi r = float_cubic_toi(toi_irrational_contact());
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.t_lo, std::sqrt(2.4 * 2.4 + 2) - 2.4, 1e-12);
}

TEST(CcdToi, WidthsOutsideTheContractAreRefused) {
  for (const double w : {0.0, 0x1p-53, 2.0, std::nan("")}) {
    EXPECT_THROW(robust_ccd_toi(toi_dyadic_contact(), w, exact::ccd_toi), std::invalid_argument);
    EXPECT_THROW(exact::ccd_toi(toi_dyadic_contact(), 0, 1, w), std::invalid_argument);
  }
}

}  // namespace
}  // namespace fdh
