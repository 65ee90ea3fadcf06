// The audit engine's `inside` count (FrameReport::inside): cloth vertices strictly inside a
// closed obstacle piece, the sphere obstacle of the shipped scenes; open pieces have no inside.
#include <gtest/gtest.h>

#include "fdh/audit/auditor.hpp"
#include "fdh/cloth/obstacle_mesh.hpp"

namespace fdh::audit {
namespace {

const Vec3 kCentre{0, 0.5, 0};
const double kRadius = 0.35;

// One cloth triangle against `obstacle`, each frame on its own (as the scene runs audit).
FrameReport one_frame(const std::vector<Vec3>& cloth, const TriMesh& obstacle) {
  Topology t;
  t.cloth_vertices = 3;
  t.cloth = {{0, 1, 2}};
  t.obstacle_vertices = int(obstacle.x.size());
  t.obstacle = obstacle.tris;
  Options o;
  o.steps = false;
  Auditor audit(t, o);
  return audit.add_frame(cloth, obstacle.x);
}

TEST(AuditInside, AParticlePlantedInTheSphereCountsOne) {
  const TriMesh ball = cloth::sphere_mesh(kCentre, kRadius);
  const FrameReport r = one_frame({kCentre, {2, 0.5, 0}, {2, 1.5, 0}}, ball);
  EXPECT_EQ(r.inside, 1);
  EXPECT_GT(r.obstacle_intersections, 0);  // its triangle leaves the sphere
}

TEST(AuditInside, AParticleOnTheSurfaceIsNotInside) {
  const TriMesh ball = cloth::sphere_mesh(kCentre, kRadius);
  const FrameReport r = one_frame({ball.x[0], {2, 0.5, 0}, {2, 1.5, 0}}, ball);
  EXPECT_EQ(r.inside, 0);
  EXPECT_GT(r.obstacle_intersections, 0);  // touching counts as meeting
}

// The case the triangle count cannot see: a cloth piece wholly inside meets no obstacle triangle.
TEST(AuditInside, APieceWhollyInsideMeetsNoTriangleButIsInside) {
  const TriMesh ball = cloth::sphere_mesh(kCentre, kRadius);
  const FrameReport r =
      one_frame({kCentre, kCentre + Vec3{0.05, 0, 0}, kCentre + Vec3{0, 0.05, 0}}, ball);
  EXPECT_EQ(r.inside, 3);
  EXPECT_EQ(r.obstacle_intersections, 0);
}

TEST(AuditInside, AnOpenPieceHasNoInsideAndAClosedOneBesideItStillCounts) {
  TriMesh open = cloth::sphere_mesh(kCentre, kRadius);
  open.tris.pop_back();
  const std::vector<Vec3> cloth = {kCentre, kCentre + Vec3{0.05, 0, 0}, {5, 0, 0}};
  EXPECT_EQ(one_frame(cloth, open).inside, 0);
  TriMesh both = open;
  both.append(cloth::box_mesh({4, -1, -1}, {6, 1, 1}));  // holds the third particle
  EXPECT_EQ(one_frame(cloth, both).inside, 1);
}

// A moving obstacle: each frame's inside is the obstacle's at that frame.
TEST(AuditInside, AMovingObstacleIsTakenWhereItIs) {
  const TriMesh ball = cloth::sphere_mesh(kCentre, kRadius);
  Topology t{3, {{0, 1, 2}}, int(ball.x.size()), ball.tris};
  Options o;
  o.steps = false;
  Auditor audit(t, o);
  const std::vector<Vec3> cloth = {kCentre, {2, 0.5, 0}, {2, 1.5, 0}};
  EXPECT_EQ(audit.add_frame(cloth, ball.x).inside, 1);
  std::vector<Vec3> away = ball.x;
  for (Vec3& p : away) p = p + Vec3{0, 0, 3};
  EXPECT_EQ(audit.add_frame(cloth, away).inside, 0);
  EXPECT_EQ(audit.add_frame(cloth, ball.x).inside, 1);
}

}  // namespace
}  // namespace fdh::audit
