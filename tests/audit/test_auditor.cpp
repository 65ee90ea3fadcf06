// The audit's engine on planted cases: clean, a vertex through a triangle, an edge through an
// edge, a frame's intersection, obstacles both ways, bad input; and the culling of flat sheets.
#include "fdh/audit/auditor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "audit_meshes.hpp"

namespace fdh::audit {
namespace {

using testing::grid;
using testing::join;
using testing::cloth_only;
using testing::Mesh;

// A wavy sheet, moving along `shift` with its wave travelling: never touching itself.
std::vector<Vec3> wavy(const Mesh& m, double phase, const Vec3& shift) {
  std::vector<Vec3> x = m.x;
  for (Vec3& p : x)
    p = p + shift + Vec3{0, 0, 0.3 * std::sin(0.5 * p.x + phase) * std::cos(0.4 * p.y)};
  return x;
}

TEST(Auditor, CleanSequenceHasNoViolation) {
  const Mesh m = grid(30, 1.0, {0, 0, 0});
  Auditor audit(cloth_only(m));
  for (int f = 0; f < 4; ++f) {
    const FrameReport r = audit.add_frame(wavy(m, 0.4 * f, {0.5 * f, 0, -3.0 * f}), {});
    EXPECT_EQ(r.frame, f);
    EXPECT_EQ(r.has_step, f > 0);
    EXPECT_EQ(r.self_intersections, 0);
    EXPECT_EQ(r.step.total(), 0);
    EXPECT_TRUE(r.violations.empty());
  }
}

// Two sheets: a 5 x 5 grid B at z = 1 whose middle vertex goes down to z = -0.5 between frames
// 1 and 2, through the square A (two triangles, wider than the spike it makes) at z = 0 below it.
struct Crossing {
  Mesh mesh;
  int vertex = 0;   // B's middle vertex
  int a_first = 0;  // A's first triangle (holds the vertex's path)
};
Crossing crossing() {
  const Mesh b = grid(5, 1.0, {0.03 - 2, 0.01 - 2, 1});
  Mesh a;
  a.x = {{-1.5, -1.5, 0}, {1.5, -1.5, 0}, {1.5, 1.5, 0}, {-1.5, 1.5, 0}};
  a.tris = {{0, 1, 2}, {0, 2, 3}};
  Crossing c;
  c.mesh = join(b, a);
  c.vertex = 12;
  c.a_first = int(b.tris.size());
  return c;
}

TEST(Auditor, FindsAVertexPushedThroughATriangle) {
  const Crossing c = crossing();
  Options o;
  o.keep = 1000;
  Auditor audit(cloth_only(c.mesh), o);
  std::vector<Vec3> x = c.mesh.x;
  EXPECT_EQ(audit.add_frame(x, {}).step.total(), 0);
  EXPECT_EQ(audit.add_frame(x, {}).step.total(), 0);
  x[c.vertex].z = -0.5;  // z = 1 - 1.5 t: through z = 0 at t* = 2/3
  const FrameReport r = audit.add_frame(x, {});
  ASSERT_GT(r.step.self_vertex_face, 0);
  ASSERT_FALSE(r.violations.empty());
  const Violation& v = r.violations[0];  // the earliest: the vertex itself
  EXPECT_EQ(v.kind, ViolationKind::SelfVertexFace);
  EXPECT_EQ(v.frame, 1);
  EXPECT_EQ(v.vertices[0], c.vertex);
  EXPECT_EQ(v.triangle, c.a_first);
  EXPECT_TRUE(v.toi.hit);
  EXPECT_LE(v.toi.t_lo, 2.0 / 3);
  EXPECT_GE(v.toi.t_hi, 2.0 / 3);
  EXPECT_LE(v.toi.t_hi - v.toi.t_lo, kDefaultToiWidth);
  // The spike stays through A: the frame intersects itself from now on.
  EXPECT_GT(r.self_intersections, 0);
  const FrameReport still = audit.add_frame(x, {});
  EXPECT_EQ(still.step.total(), 0);
  EXPECT_EQ(still.self_intersections, r.self_intersections);
}

TEST(Auditor, FindsAnIntersectionInTheFirstFrame) {
  Crossing c = crossing();
  c.mesh.x[c.vertex].z = -0.5;
  Options o;
  o.keep = 1000;
  Auditor audit(cloth_only(c.mesh), o);
  const FrameReport r = audit.add_frame(c.mesh.x, {});
  EXPECT_FALSE(r.has_step);
  const auto expected =
      testing::brute_force(cloth_only(c.mesh), c.mesh.x, c.mesh.x, {}, {}, 0, false);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(r.self_intersections, long(expected.size()));
  ASSERT_EQ(r.violations.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(r.violations[i].kind, ViolationKind::SelfIntersection);
    EXPECT_EQ(r.violations[i].triangles, expected[i].triangles);
    // The frame's query: one triangle's edge through the other, a still segment-triangle.
    EXPECT_TRUE(r.violations[i].query.is_static_vf());
  }
}

// Triangle P hangs below the x axis in the plane y = 0; triangle Q, in the plane x = 0, comes
// down from above with its lower edge across the x axis: edge through edge at t* = 2/3.
TEST(Auditor, FindsAnEdgePassingThroughAnEdge) {
  Mesh m;
  m.x = {{-1, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, -1, 1}, {0, 1, 1}, {0, 0, 2}};
  m.tris = {{0, 1, 2}, {3, 4, 5}};
  Auditor audit(cloth_only(m));
  std::vector<Vec3> x = m.x;
  EXPECT_EQ(audit.add_frame(x, {}).self_intersections, 0);
  for (int i = 3; i < 6; ++i) x[i].z -= 1.5;
  const FrameReport r = audit.add_frame(x, {});
  EXPECT_EQ(r.step.self_edge_edge, 1);
  EXPECT_EQ(r.step.self_vertex_face, 0);
  EXPECT_EQ(r.self_intersections, 1);  // Q's lower edge now through P
  ASSERT_EQ(r.violations.size(), 2u);
  const Violation& v = r.violations[0];
  EXPECT_EQ(v.kind, ViolationKind::SelfEdgeEdge);
  EXPECT_EQ(v.frame, 0);
  const std::array<int, 4> ee = v.vertices;
  EXPECT_TRUE((ee == std::array<int, 4>{0, 1, 3, 4}) || (ee == std::array<int, 4>{3, 4, 0, 1}));
  EXPECT_LE(v.toi.t_lo, 2.0 / 3);
  EXPECT_GE(v.toi.t_hi, 2.0 / 3);
  EXPECT_EQ(r.violations[1].kind, ViolationKind::SelfIntersection);
  EXPECT_EQ(r.violations[1].frame, 1);
  EXPECT_EQ(r.violations[1].triangles, (std::array<int, 2>{0, 1}));
}

// The edge-edge case again with P as a still obstacle and Q as the cloth.
TEST(Auditor, FindsAClothEdgePassingThroughAnObstacleEdge) {
  Topology t;
  t.cloth_vertices = 3;
  t.cloth = {{0, 1, 2}};
  t.obstacle_vertices = 3;
  t.obstacle = {{0, 1, 2}};
  const std::vector<Vec3> p = {{-1, 0, 0}, {1, 0, 0}, {0, 0, -1}};
  std::vector<Vec3> q = {{0, -1, 1}, {0, 1, 1}, {0, 0, 2}};
  Auditor audit(t);
  EXPECT_EQ(audit.add_frame(q, p).obstacle_intersections, 0);
  for (Vec3& x : q) x.z -= 1.5;
  const FrameReport r = audit.add_frame(q, p);
  EXPECT_EQ(r.step.cloth_edge_obstacle_edge, 1);
  EXPECT_EQ(r.step.cloth_vertex_obstacle + r.step.obstacle_vertex_cloth, 0);
  EXPECT_EQ(r.obstacle_intersections, 1);
  ASSERT_EQ(r.violations.size(), 2u);
  const Violation& v = r.violations[0];
  EXPECT_EQ(v.kind, ViolationKind::ClothEdgeObstacleEdge);
  EXPECT_EQ(v.vertices, (std::array<int, 4>{0, 1, 0, 1}));  // cloth edge, then obstacle edge
  EXPECT_LE(v.toi.t_lo, 2.0 / 3);
  EXPECT_GE(v.toi.t_hi, 2.0 / 3);
  EXPECT_EQ(r.violations[1].kind, ViolationKind::ObstacleIntersection);
  EXPECT_EQ(r.violations[1].triangles, (std::array<int, 2>{0, 0}));
}

TEST(Auditor, FindsAClothVertexThroughAStillObstacle) {
  const Mesh cloth = grid(4, 1.0, {-1.4, -1.45, 1});
  Mesh table;  // a 6 x 6 square at z = 0, two triangles
  table.x = {{-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}};
  table.tris = {{0, 1, 2}, {0, 2, 3}};
  Topology t = cloth_only(cloth);
  t.obstacle_vertices = 4;
  t.obstacle = table.tris;
  Options o;
  o.keep = 100;
  Auditor audit(t, o);
  std::vector<Vec3> x = cloth.x;
  EXPECT_EQ(audit.add_frame(x, table.x).obstacle_intersections, 0);
  x[5].z = -1;  // an inner vertex, at (-0.4, -0.45): through the table at t* = 1/2
  const FrameReport r = audit.add_frame(x, table.x);
  EXPECT_EQ(r.step.cloth_vertex_obstacle, 1);
  EXPECT_EQ(r.step.obstacle_vertex_cloth, 0);
  EXPECT_GT(r.obstacle_intersections, 0);
  ASSERT_FALSE(r.violations.empty());
  const Violation& v = r.violations[0];
  EXPECT_EQ(v.kind, ViolationKind::ClothVertexObstacle);
  EXPECT_EQ(v.vertices[0], 5);
  EXPECT_EQ(v.triangle, 0);  // (-0.4, -0.45) is below the table's diagonal y = x
  EXPECT_LE(v.toi.t_lo, 0.5);
  EXPECT_GE(v.toi.t_hi, 0.5);
}

TEST(Auditor, FindsAnObstacleVertexPokingThroughTheCloth) {
  const Mesh cloth = grid(3, 1.0, {-1, -1, 0});
  Mesh spike;  // a steep tetrahedron whose apex (vertex 3) rises through the cloth
  spike.x = {{0.3, 0.1, -2}, {0.7, 0.1, -2}, {0.5, 0.35, -2}, {0.5, 0.2, -1}};
  spike.tris = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  Topology t = cloth_only(cloth);
  t.obstacle_vertices = 4;
  t.obstacle = spike.tris;
  Options o;
  o.keep = 100;
  Auditor audit(t, o);
  EXPECT_EQ(audit.add_frame(cloth.x, spike.x).step.total(), 0);
  std::vector<Vec3> y = spike.x;
  for (Vec3& p : y) p.z += 1.1;  // the apex from z = -1 to 0.1: through z = 0 at 1 / 1.1
  const double t_star = 1 / (y[3].z + 1);
  const FrameReport r = audit.add_frame(cloth.x, y);
  EXPECT_EQ(r.step.obstacle_vertex_cloth, 1);
  EXPECT_EQ(r.step.cloth_vertex_obstacle, 0);
  EXPECT_EQ(r.step.cloth_edge_obstacle_edge, 0);
  ASSERT_FALSE(r.violations.empty());
  const Violation& v = r.violations[0];
  EXPECT_EQ(v.kind, ViolationKind::ObstacleVertexCloth);
  EXPECT_EQ(v.vertices[0], 3);
  // (0.5, 0.2) lies in the cell [0, 1]^2's first triangle, {4, 5, 8} (below its diagonal).
  EXPECT_EQ(v.triangle, 6);
  EXPECT_EQ((std::array<int, 3>{v.vertices[1], v.vertices[2], v.vertices[3]}),
            (std::array<int, 3>{4, 5, 8}));
  EXPECT_LE(v.toi.t_lo, t_star + 1e-12);
  EXPECT_GE(v.toi.t_hi, t_star - 1e-12);
  EXPECT_GT(r.obstacle_intersections, 0);
}

// A flat sheet falling 28 edge lengths a frame (exactly flat: z equal): the normal cones cull
// everything.
TEST(Auditor, FlatFallingSheetMakesNoCandidates) {
  const Mesh m = grid(100, 1.0, {0, 0, 0});
  Auditor audit(cloth_only(m));
  std::vector<Vec3> x = m.x;
  long candidates = 0;
  for (int f = 0; f < 3; ++f) {
    const FrameReport r = audit.add_frame(x, {});
    candidates += r.step.candidates + r.static_candidates;
    EXPECT_EQ(r.step.total() + r.self_intersections, 0);
    for (Vec3& p : x) p.z -= 28;
  }
  EXPECT_EQ(candidates, 0);  // the whole sheet is one flat patch: the root is culled
}

// Points only (no triangle), and obstacles only: nothing to pair, nothing found.
TEST(Auditor, AuditsMeshesWithoutTriangles) {
  Topology t;
  t.cloth_vertices = 2;
  t.obstacle_vertices = 3;
  t.obstacle = {{0, 1, 2}};
  Auditor audit(t);
  const std::vector<Vec3> y = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(audit.add_frame({{0.2, 0.2, 1}, {5, 5, 5}}, y).obstacle_intersections, 0);
  const FrameReport r = audit.add_frame({{0.2, 0.2, -1}, {5, 5, 5}}, y);
  EXPECT_EQ(r.step.total(), 0);  // a vertex in no triangle is not tested (Topology)
  EXPECT_EQ(r.step.candidates, 0);
}

TEST(Auditor, RefusesBadInput) {
  Topology t;
  t.cloth_vertices = 3;
  t.cloth = {{0, 1, 3}};
  EXPECT_THROW(Auditor{t}, std::invalid_argument);
  t.cloth = {{0, 1, 1}};
  EXPECT_THROW(Auditor{t}, std::invalid_argument);
  t.cloth = {{0, 1, 2}};
  Options o;
  o.k = 7;
  EXPECT_THROW(Auditor(t, o), std::invalid_argument);
  Auditor audit(t);
  EXPECT_THROW(audit.add_frame({{0, 0, 0}, {1, 0, 0}}, {}), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(audit.add_frame({{0, 0, 0}, {1, 0, 0}, {0, nan, 0}}, {}), std::invalid_argument);
  EXPECT_THROW(audit.add_frame({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}}),
               std::invalid_argument);
  EXPECT_EQ(audit.add_frame({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}).frame, 0);
}

}  // namespace
}  // namespace fdh::audit
