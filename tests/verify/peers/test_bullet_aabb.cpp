// Bullet's boxes behind their adapter (verify/peers/src/bullet_aabb.cpp), in double precision.
#include <gtest/gtest.h>

#include "fdh/check/checker.hpp"
#include "fdh/gen/point_sets.hpp"
#include "verify/peers/peer_methods.hpp"

namespace fdh::verify {
namespace {

// Coordinates with few bits: centre and half extent are exact, so every box is the exact AABB,
// and sets sharing a corner overlap.
TEST(BulletAabb, DyadicBoxesAreExact) {
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 2, 3}, {-4, 1, 0.5}}, b = {{1, 2, 3}, {5, 5, 5}};
  for (const BoxMethod& m : peer_library("bullet").methods) {
    double lo[3], hi[3];
    m.build(a.data(), a.size(), lo, hi);
    EXPECT_EQ(lo[0], -4) << m.name;
    EXPECT_EQ(hi[2], 3) << m.name;
    EXPECT_EQ(check_box(m, a.data(), a.size()), -1) << m.name;
    EXPECT_TRUE(check_overlap(m, a, b).said) << m.name;
  }
}

// The broad phase's btDbvtAabbMm::FromPoints takes per-axis min and max: exact on any points.
TEST(BulletAabb, FromPointsContainsEveryRandomSet) {
  const BoxMethod m = peer_method("bullet", "dbvt-from-points");
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const std::vector<Vec3> pts = random_point_set(seed);
    EXPECT_EQ(check_box(m, pts.data(), pts.size()), -1) << seed;
  }
}

// A shape's getAabb goes through centre and half extent: for x in [1, 1 + 3u] (u = 2^-52) the
// centre 0.5·fl(2 + 3u) = 1 + 2u and the half extent 1.5u give the maximum fl(1 + 3.5u) = 1 + 4u,
// not 1 + 3u. FromPoints keeps 1 + 3u.
TEST(BulletAabb, CentreAndExtentRound) {
  const Vec3 pts[2] = {{1, 0, 0}, {1 + 3 * 0x1p-52, 0, 0}};
  for (const char* name : {"convex-hull-aabb", "bvh-trimesh-aabb", "dbvt-from-points"}) {
    double lo[3], hi[3];
    peer_method("bullet", name).build(pts, 2, lo, hi);
    EXPECT_EQ(lo[0], 1) << name;
    EXPECT_EQ(hi[0], std::string(name) == "dbvt-from-points" ? 1 + 3 * 0x1p-52 : 1 + 0x1p-50)
        << name;
  }
}

}  // namespace
}  // namespace fdh::verify
