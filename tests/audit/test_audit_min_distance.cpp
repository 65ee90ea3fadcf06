// `audit --min-distance D` in the engine (issue 31): the proximity kinds decided exactly at D's
// double value (distance <= D counts), kept apart from the intersection kinds; the nearest pair
// with its exact distance; the rule on pairs near by construction on a fine sheet.
#include <gtest/gtest.h>

#include <cmath>

#include "audit_meshes.hpp"
#include "fdh/audit/auditor.hpp"
#include "fdh/audit/counts.hpp"
#include "fdh/exact/distance.hpp"

// A named namespace, not an anonymous one: the tests are built as one unity file.
namespace fdh::audit::min_distance_tests {

using testing::grid;
using testing::join;
using testing::cloth_only;
using testing::Mesh;

// Every frame through an auditor at D; the counts summed.
AuditCounts run(const Topology& t, const std::vector<std::vector<Vec3>>& cloth,
                const std::vector<std::vector<Vec3>>& obstacle, double d,
                std::vector<FrameReport>* reports = nullptr) {
  Options o;
  o.min_distance = d;
  o.keep = 1000;
  Auditor audit(t, o);
  AuditCounts c;
  for (std::size_t f = 0; f < cloth.size(); ++f) {
    const FrameReport r =
        audit.add_frame(cloth[f], obstacle.empty() ? std::vector<Vec3>{} : obstacle[f]);
    c.add(counts_of(r));
    if (reports) reports->push_back(r);
  }
  return c;
}

// Two 6 x 6 sheets, B 0.5 above A in frame 0 and exactly 1/64 above it in frames 1 and 2.
struct Sheets {
  Mesh mesh;
  std::vector<std::vector<Vec3>> frames;
};
Sheets sheets() {
  const Mesh a = grid(6, 0.1, {0, 0, 0});
  Sheets s;
  s.mesh = join(a, grid(6, 0.1, {0, 0, 0.5}));
  s.frames.push_back(s.mesh.x);
  std::vector<Vec3> near = s.mesh.x;
  for (std::size_t i = a.x.size(); i < near.size(); ++i) near[i].z = 0x1p-6;
  s.frames.push_back(near);
  s.frames.push_back(near);
  return s;
}

TEST(AuditMinDistance, TwoSheetsAt1Over64AreCleanWithoutD) {
  const Sheets s = sheets();
  const AuditCounts c = run(cloth_only(s.mesh), s.frames, {}, 0);
  EXPECT_EQ(c.total(), 0);
  EXPECT_EQ(c.self_proximity, 0);
}

TEST(AuditMinDistance, TwoSheetsAt1Over64AreAViolationAtDEqualToIt) {
  const Sheets s = sheets();
  std::vector<FrameReport> reports;
  const AuditCounts c = run(cloth_only(s.mesh), s.frames, {}, 0.015625, &reports);
  EXPECT_GT(c.total(), 0);
  EXPECT_EQ(c.self_intersections, 0);
  EXPECT_EQ(c.step.self_vertex_face + c.step.self_edge_edge, 0);  // never touching
  EXPECT_GT(c.self_proximity, 0);
  EXPECT_GT(c.step.self_vertex_face_near, 0);
  EXPECT_EQ(reports[0].self_proximity, 0);  // 0.5 apart
  EXPECT_EQ(reports[1].self_proximity, reports[2].self_proximity);
  // Within D only at the end of the step into frame 1: its earliest time is t = 1.
  for (const Violation& v : reports[1].violations)
    if (is_step(v.kind)) {
      EXPECT_TRUE(is_proximity(v.kind));
      EXPECT_EQ(v.query.min_distance, 0.015625);
      EXPECT_EQ(v.toi.t_hi, 1.0);
    }
  // The nearest pair: exactly 1/64 apart.
  EXPECT_EQ(reports[1].nearest[0].squared, "1/4096");
  EXPECT_LE(reports[1].nearest[0].lo, 0.015625);
  EXPECT_GE(reports[1].nearest[0].hi, 0.015625);
  EXPECT_EQ(reports[1].nearest[1].frame, -1);  // no obstacle
}

TEST(AuditMinDistance, TwoSheetsAt1Over64AreCleanJustBelowIt) {
  const Sheets s = sheets();
  std::vector<FrameReport> reports;
  const AuditCounts c = run(cloth_only(s.mesh), s.frames, {}, 0.0156249, &reports);
  EXPECT_EQ(c.total(), 0);
  // The sheets' boxes are 1/64 apart, more than D: the broad phase looks at no pair.
  EXPECT_EQ(reports[2].nearest[0].frame, -1);
}

// A sheet (the cloth) at z = 0 and an obstacle: a triangle standing on its tip, the tip rising
// from 0.5 below the sheet to 1/128 below it.
struct Tip {
  Mesh cloth, obstacle;
  std::vector<std::vector<Vec3>> frames, obstacles;
};
Tip tip() {
  Tip t;
  t.cloth = grid(6, 0.1, {0, 0, 0});
  t.obstacle.x = {{0.23, 0.17, -0.5}, {0.1, 0.1, -1.5}, {0.4, 0.3, -1.5}};
  t.obstacle.tris = {{0, 1, 2}};
  t.frames = {t.cloth.x, t.cloth.x};
  std::vector<Vec3> up = t.obstacle.x;
  for (Vec3& p : up) p.z += 0.5 - 0x1p-7;
  t.obstacles = {t.obstacle.x, up};
  return t;
}

TEST(AuditMinDistance, AVertexRisingTo1Over128BelowASheet) {
  const Tip t = tip();
  Topology top;
  top.cloth_vertices = int(t.cloth.x.size()), top.cloth = t.cloth.tris;
  top.obstacle_vertices = 3, top.obstacle = t.obstacle.tris;
  EXPECT_EQ(run(top, t.frames, t.obstacles, 0).total(), 0);
  const AuditCounts at = run(top, t.frames, t.obstacles, 0.01);
  EXPECT_GT(at.obstacle_proximity, 0);
  EXPECT_GT(at.step.obstacle_vertex_cloth_near, 0);
  EXPECT_EQ(at.obstacle_intersections + at.step.obstacle_vertex_cloth, 0);
  EXPECT_EQ(run(top, t.frames, t.obstacles, 0.007).total(), 0);
}

TEST(AuditMinDistance, ContactStaysItsOwnKind) {
  // The tip rises through the sheet: contact kinds, not proximity, for the pairs that meet.
  Tip t = tip();
  for (Vec3& p : t.obstacles[1]) p.z += 0.1;
  Topology top;
  top.cloth_vertices = int(t.cloth.x.size()), top.cloth = t.cloth.tris;
  top.obstacle_vertices = 3, top.obstacle = t.obstacle.tris;
  const AuditCounts none = run(top, t.frames, t.obstacles, 0);
  const AuditCounts at = run(top, t.frames, t.obstacles, 0.01);
  EXPECT_GT(none.obstacle_intersections, 0);
  EXPECT_EQ(at.obstacle_intersections, none.obstacle_intersections);
  EXPECT_EQ(at.step.obstacle_vertex_cloth, none.step.obstacle_vertex_cloth);
  EXPECT_EQ(at.step.cloth_edge_obstacle_edge, none.step.cloth_edge_obstacle_edge);
}

// A 200 x 200 sheet, 2 m square (vertices 0.01 apart, below D = 0.015), rippling gently: the
// near rule leaves its neighbours out, so no proximity is counted; without the rule they flood.
TEST(AuditMinDistance, AFineSheetDoesNotFloodAtBlendersDistance) {
  const Mesh m = grid(200, 2.0 / 199, {-1, -1, 1});
  std::vector<std::vector<Vec3>> frames;
  for (int f = 0; f < 3; ++f) {
    std::vector<Vec3> x = m.x;
    for (Vec3& p : x) p.z += 0.02 * f * std::sin(3 * p.x) - 0.01 * f;
    frames.push_back(x);
  }
  std::vector<FrameReport> reports;
  const AuditCounts c = run(cloth_only(m), frames, {}, 0.015, &reports);
  EXPECT_EQ(c.total(), 0);
  EXPECT_GT(c.excluded.rings, 0);
  // Every pair within reach of D is a neighbour the rings leave out: no nearest pair, or one
  // beyond D.
  EXPECT_TRUE(reports[2].nearest[0].frame < 0 || reports[2].nearest[0].lo > 0.015);

  // Without the rule, a 30 x 30 corner of the same sheet alone floods at rest.
  const Mesh corner = grid(30, 2.0 / 199, {-1, -1, 1});
  Options bare;
  bare.min_distance = 0.015, bare.near_rings = 0, bare.near_first_frame = false;
  Auditor flood(cloth_only(corner), bare);
  EXPECT_GT(counts_of(flood.add_frame(corner.x, {})).self_proximity, 1000);
}

TEST(AuditMinDistance, TheFirstFrameRuleLeavesOutPairsNearAtTheStart) {
  // Sheet B 1/128 above A from the start, then still: near in the first frame, left out.
  Sheets s = sheets();
  for (auto& x : s.frames)
    for (std::size_t i = 36; i < x.size(); ++i) x[i].z = 0x1p-7;
  std::vector<FrameReport> reports;
  const AuditCounts c = run(cloth_only(s.mesh), s.frames, {}, 0.01, &reports);
  EXPECT_EQ(c.total(), 0);
  EXPECT_GT(c.excluded.first_frame, 0);
  EXPECT_GT(reports[0].excluded.first_frame_pairs, 0);
  Options o;
  o.min_distance = 0.01, o.near_first_frame = false;
  Auditor counted(cloth_only(s.mesh), o);
  EXPECT_GT(counts_of(counted.add_frame(s.frames[0], {})).self_proximity, 0);
}

TEST(AuditMinDistance, ExactTriangleDistance) {
  const std::array<Vec3, 3> a{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  const std::array<Vec3, 3> b{Vec3{0, 0, 0x1p-6}, Vec3{1, 0, 0x1p-6}, Vec3{0, 1, 1}};
  EXPECT_EQ(exact::triangle_distance(a, b).squared, "1/4096");
  EXPECT_TRUE(exact::triangles_within(a, b, 0.015625));
  EXPECT_FALSE(exact::triangles_within(a, b, std::nextafter(0.015625, 0.0)));
  const std::array<Vec3, 3> c{Vec3{0.2, 0.2, -1}, Vec3{0.3, 0.2, 1}, Vec3{0.2, 0.3, 1}};
  EXPECT_EQ(exact::triangle_distance(a, c).squared, "0");  // they cross
}

TEST(AuditMinDistance, RefusesABadDistance) {
  Options o;
  o.min_distance = -1;
  EXPECT_THROW(Auditor(cloth_only(grid(3, 1, {0, 0, 0})), o), std::invalid_argument);
  o.min_distance = NAN;
  EXPECT_THROW(Auditor(cloth_only(grid(3, 1, {0, 0, 0})), o), std::invalid_argument);
}

}  // namespace fdh::audit::min_distance_tests
