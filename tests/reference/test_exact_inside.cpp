// exact::ClosedMesh (fdh/exact/inside.hpp): strictly inside a closed mesh, exactly on the given
// doubles (a hair inside is inside, the surface is not); an open mesh has no inside.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fdh/cloth/obstacle_mesh.hpp"
#include "fdh/exact/inside.hpp"

namespace fdh::exact {
namespace {

TEST(ExactInside, StrictlyInsideABoxExactly) {
  const ClosedMesh box(cloth::box_mesh({0, 0, 0}, {1, 1, 1}));
  EXPECT_TRUE(box.strictly_inside({0.5, 0.5, 0.5}));
  EXPECT_FALSE(box.strictly_inside({1, 0.5, 0.5}));  // on a face
  EXPECT_FALSE(box.strictly_inside({1, 1, 0.5}));    // on an edge
  EXPECT_FALSE(box.strictly_inside({0, 0, 0}));      // a corner
  EXPECT_FALSE(box.strictly_inside({2, 0.5, 0.5}));
  // A hair either side of a face: exact, not within a tolerance.
  EXPECT_TRUE(box.strictly_inside({std::nextafter(1.0, 0.0), 0.5, 0.5}));
  EXPECT_FALSE(box.strictly_inside({std::nextafter(1.0, 2.0), 0.5, 0.5}));
}

TEST(ExactInside, TheSphereObstacleHasAnInsideAndItsVerticesAreNotInIt) {
  const TriMesh ball = cloth::sphere_mesh({0, 0.5, 0}, 0.35);
  const ClosedMesh inside(ball);
  EXPECT_TRUE(inside.strictly_inside({0, 0.5, 0}));
  EXPECT_TRUE(inside.strictly_inside({0.3, 0.5, 0}));
  EXPECT_FALSE(inside.strictly_inside({0.4, 0.5, 0}));
  for (const Vec3& p : ball.x) ASSERT_FALSE(inside.strictly_inside(p));
}

TEST(ExactInside, AnOpenMeshHasNoInside) {
  TriMesh open = cloth::box_mesh({0, 0, 0}, {1, 1, 1});
  EXPECT_TRUE(is_closed_manifold(open));
  open.tris.pop_back();
  EXPECT_FALSE(is_closed_manifold(open));
  EXPECT_THROW(ClosedMesh{open}, std::invalid_argument);
  EXPECT_FALSE(is_closed_manifold(TriMesh{}));
}

}  // namespace
}  // namespace fdh::exact
