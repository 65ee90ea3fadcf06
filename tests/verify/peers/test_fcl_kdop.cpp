// FCL's k-DOPs behind their adapter (verify/peers/src/fcl_kdop.cpp): the slab directions are
// FCL's, in its order, and the checker evaluates its boxes.
#include <gtest/gtest.h>

#include "fdh/check/checker.hpp"
#include "verify/peers/peer_methods.hpp"

namespace fdh::verify {
namespace {

// A point with small integer coordinates: every projection is exact, so slab s of its box is
// the point's projection on the adapter's direction s (distinct for each of FCL's directions).
TEST(FclKdop, SlabsFollowFclsDirectionsInItsOrder) {
  const Vec3 p{1, 2, 4};
  for (const char* name : {"kdop16", "kdop18", "kdop24"}) {
    const BoxMethod m = peer_method("fcl", name);
    std::vector<double> lo(m.directions.size()), hi(lo.size());
    m.build(&p, 1, lo.data(), hi.data());
    for (std::size_t s = 0; s < lo.size(); ++s) {
      EXPECT_EQ(lo[s], project(m.directions[s], p)) << name << " slab " << s;
      EXPECT_EQ(hi[s], lo[s]) << name << " slab " << s;
    }
  }
  // FCL's order after the axes (kDOP-inl.h, getDistances): x+y, x+z, y+z, x-y, x-z, y-z,
  // (x+y)-z, (x+z)-y, (y+z)-x.
  const BoxMethod k24 = peer_method("fcl", "kdop24");
  std::vector<double> lo(12), hi(12);
  k24.build(&p, 1, lo.data(), hi.data());
  EXPECT_EQ(lo, (std::vector<double>{1, 2, 4, 3, 5, 6, -1, -3, -2, -1, 3, 5}));
}

TEST(FclKdop, ExactSumsAreContainedAndTouchingSetsOverlap) {
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 2, 3}, {-4, 1, 0.5}}, b = {{1, 2, 3}, {5, 5, 5}};
  for (const BoxMethod& m : peer_library("fcl").methods) {
    EXPECT_EQ(check_box(m, a.data(), a.size()), -1) << m.name;
    const Verdicts v = check_overlap(m, a, b);
    EXPECT_TRUE(v.twin && v.said) << m.name;
  }
}

// 0.1 + 0.2 rounds up, 0.1 + 0.7 rounds down: FCL's x+y slab (slab 3) misses the exact extent,
// which the project's 18-DOP, pushed outward, contains.
TEST(FclKdop, ARoundedSumMissesTheExactExtent) {
  const Vec3 pts[2] = {{0.1, 0.2, 0}, {0.1, 0.7, 0}};
  EXPECT_EQ(check_box(peer_method("fcl", "kdop16"), pts, 2), 3);
  for (const BoxMethod& m : all_box_methods()) EXPECT_EQ(check_box(m, pts, 2), -1) << m.k;
}

}  // namespace
}  // namespace fdh::verify
