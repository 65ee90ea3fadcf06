// Point sets for the peers (fdh/gen/point_sets.hpp) and their shrinking
// (fdh/gen/shrink_point_sets.hpp).
#include <gtest/gtest.h>

#include "fdh/exact/kdop.hpp"
#include "fdh/gen/point_sets.hpp"
#include "fdh/gen/shrink_point_sets.hpp"

namespace fdh::verify {
namespace {

TEST(PointSets, SameSeedSameSets) {
  EXPECT_EQ(random_point_set(7), random_point_set(7));
  EXPECT_EQ(touching_point_sets(7).a, touching_point_sets(7).a);
  EXPECT_NE(random_point_set(7), random_point_set(8));
}

// Touching by construction: the exact FDHs along the contact direction meet and do not cross
// (the two contact points have the same exact projection), checked with exact rationals.
TEST(PointSets, TouchingSetsTouchAlongTheirPlane) {
  int planes = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const TouchingSets t = touching_point_sets(seed);
    ASSERT_FALSE(t.a.empty());
    ASSERT_FALSE(t.b.empty());
    if (t.contact == "shared point") {
      EXPECT_EQ(t.a.front(), t.b.front()) << seed;
      continue;
    }
    ++planes;
    int d[3];
    ASSERT_EQ(std::sscanf(t.contact.c_str(), "plane (%d,%d,%d)", &d[0], &d[1], &d[2]), 3);
    const std::vector<Direction> dir = {{d[0], d[1], d[2]}};
    // The contact points alone overlap along d; a's far side lies below, b's above.
    EXPECT_TRUE(exact::kdops_overlap(dir, &t.a.front(), 1, &t.b.front(), 1)) << seed;
  }
  EXPECT_GT(planes, 150);
}

// "Some point has x > 1.5": shrinks to one point whose other coordinates are 0 and whose x has
// few bits, near the origin.
TEST(ShrinkPointSets, KeepsTheFailureWhileItShrinks) {
  const PointSets start = {random_point_set(3), {{2.718281828459045, -1e6, 3.3}}};
  const auto fails = [](const PointSets& s) {
    for (const auto& set : s)
      for (const Vec3& p : set)
        if (p.x > 1.5) return true;
    return false;
  };
  ASSERT_TRUE(fails(start));
  const PointSets small = shrink_point_sets(start, fails);
  EXPECT_TRUE(fails(small));
  EXPECT_LT(point_sets_size(small), point_sets_size(start));
  ASSERT_EQ(small.size(), 2u);
  const std::vector<Vec3>& holder = small[0].front().x > 1.5 ? small[0] : small[1];
  EXPECT_EQ(holder.front().y, 0);
  EXPECT_EQ(holder.front().z, 0);
  EXPECT_EQ(holder.front().x, 2);  // the shortest value above 1.5
}

}  // namespace
}  // namespace fdh::verify
