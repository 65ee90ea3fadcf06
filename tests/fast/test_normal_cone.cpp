// The normal-cone predicates of the self-collision culling (fdh/normal_cone.hpp) on cases whose
// answer is known by hand.
#include "fdh/normal_cone.hpp"

#include <gtest/gtest.h>

#include <bitset>

namespace fdh {
namespace {

TEST(NormalCone, ALevelTriangleLeansTowardsTheNineUpwardDirections) {
  // p × q = (0, 0, 1) × (1, 0, 0) = (0, 1, 0): up, and standing still.
  const Vec3 p{0, 0, 1}, q{1, 0, 0};
  const DirectionMask m = positive_directions(swept_normals(p, p, q, q));
  // The 13 directions with a +1 y coordinate (9 of them: (0,1,0), 4 corners, 4 edges), each
  // either as itself or as its opposite.
  EXPECT_EQ(std::bitset<32>(m).count(), 9u);
  EXPECT_TRUE(m & 1u << 2);   // +y
  EXPECT_FALSE(m & 1u << 3);  // -y
  EXPECT_FALSE(m & 1u << 0);  // +x: perpendicular, not positive
  EXPECT_EQ(best_direction(m, {0, 1, 0}), 2);
}

TEST(NormalCone, ATriangleThatFlipsOverTheStepLeansNowhere) {
  // q swings from +x to -x: the normal goes from +y through 0 to -y.
  const Vec3 p{0, 0, 1};
  EXPECT_EQ(positive_directions(swept_normals(p, p, {1, 0, 0}, {-1, 0, 0})), 0u);
  // A tilt that keeps it up keeps +y.
  EXPECT_TRUE(positive_directions(swept_normals(p, p, {1, 0, 0}, {1, 0.5, 0})) & 1u << 2);
}

TEST(NormalCone, ADegenerateTriangleLeansNowhere) {
  const Vec3 p{0, 0, 1};
  EXPECT_EQ(positive_directions(swept_normals(p, p, p, p)), 0u);
}

TEST(NormalCone, ASquareContourIsStarShapedOnlyCounterClockwiseAndOnce) {
  // A unit square in the x-z plane; seen from +y, 0 -> 1 -> 2 -> 3 turns counter-clockwise
  // (the winding of the cloth's triangles: (0,0) -> (0,1) in z first).
  const std::vector<Vec3> x = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
  const Vec3 m{0.5, 0, 0.5};
  const int up = 2;
  EXPECT_TRUE(contour_is_star_shaped({0, 1, 2, 3}, x, x, m, m, up));
  EXPECT_FALSE(contour_is_star_shaped({3, 2, 1, 0}, x, x, m, m, up));  // clockwise
  EXPECT_FALSE(contour_is_star_shaped({0, 1, 2, 3}, x, x, {2, 0, 0.5}, {2, 0, 0.5}, up));
  // Around twice: every edge turns positively, but the contour is not simple.
  EXPECT_FALSE(contour_is_star_shaped({0, 1, 2, 3, 0, 1, 2, 3}, x, x, m, m, up));
  // Moving: the far side sweeps across the centre during the step.
  std::vector<Vec3> x1 = x;
  x1[2] = {-1, 0, 1};
  x1[3] = {-1, 0, 0};
  EXPECT_FALSE(contour_is_star_shaped({0, 1, 2, 3}, x, x1, m, m, up));
}

}  // namespace
}  // namespace fdh
