// The audit's certificate (fdh/audit_job/audit_report.hpp) from frame reports made by hand: counts,
// the first violation, the cap, case files, and the JSON's and Markdown's agreement.
#include "fdh/audit_job/audit_report.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace fdh::verify {
namespace {

using audit::ViolationKind;

audit::Topology square() {
  audit::Topology t;
  t.cloth_vertices = 4, t.cloth = {{0, 1, 2}, {0, 2, 3}};
  t.obstacle_vertices = 3, t.obstacle = {{0, 1, 2}};
  return t;
}

audit::Violation step_violation(int frame, double t) {
  audit::Violation v;
  v.kind = ViolationKind::ClothVertexObstacle;
  v.frame = frame, v.vertices = {3, 0, 1, 2}, v.triangle = 0;
  v.toi.hit = true, v.toi.t_lo = t, v.toi.t_hi = t + 0x1p-40;
  return v;
}

TEST(AuditReport, CountsTheFirstViolationAndTheCap) {
  AuditReport r(square(), {}, 2, true);
  audit::FrameReport f0;
  EXPECT_FALSE(r.add(f0));
  EXPECT_TRUE(r.clean());
  audit::FrameReport f1;
  f1.frame = 1, f1.has_step = true, f1.step.cloth_vertex_obstacle = 2, f1.step.candidates = 5;
  f1.obstacle_intersections = 1, f1.static_candidates = 3;
  f1.violations = {step_violation(0, 0.25), step_violation(0, 0.5)};
  audit::Violation inside;
  inside.kind = ViolationKind::ObstacleIntersection, inside.frame = 1, inside.triangles = {1, 0};
  f1.violations.push_back(inside);
  Places cv;
  cv.add("a.obj", std::make_shared<std::vector<int>>(std::vector<int>{2, 3, 4, 5}));
  Places ov;
  ov.add("o.obj", std::make_shared<std::vector<int>>(std::vector<int>{7, 8, 9}));
  const FramePlaces start{&cv, nullptr, &ov, nullptr};
  EXPECT_TRUE(r.add(f1, &start, nullptr));
  EXPECT_FALSE(r.clean());
  EXPECT_EQ(r.exit_status(), 1);
  ASSERT_EQ(r.kept().size(), 2u);  // the cap
  EXPECT_EQ(r.kept()[0].places,
            (std::vector<std::string>{"a.obj:5", "o.obj:7", "o.obj:8", "o.obj:9"}));
  EXPECT_EQ(r.kept()[0].case_file, "cases/001-cloth-vertex-obstacle-step-0.vf");
  const std::vector<QueryRecord> cases = r.case_records();
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[1].truth, Truth::Yes);
  r.finish(1.5);
  const nlohmann::ordered_json j = r.json();
  EXPECT_EQ(j["clean"], false);
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(j["steps"], 1);
  EXPECT_EQ(j["violations"], 3);
  EXPECT_EQ(j["totals"]["cloth-vertex-obstacle"], 2);
  EXPECT_EQ(j["totals"]["obstacle-intersection"], 1);
  EXPECT_EQ(j["candidates"]["ccd"], 5);
  EXPECT_EQ(j["first_violation"]["toi"]["t_lo"], 0.25);
  EXPECT_EQ(j["first_violation"]["to_frame"], 1);
  EXPECT_EQ(j["per_frame"][0].size(), 3u);  // frame 0 has no step
  EXPECT_EQ(j["per_frame"][1]["cloth-vertex-obstacle"], 2);
  EXPECT_EQ(j["cost"]["wall_seconds"], 1.5);
  EXPECT_GT(j["cost"]["peak_memory_bytes"].get<long>(), 0);
  EXPECT_NE(r.markdown().find(r.summary_line()), std::string::npos);
  EXPECT_NE(r.text().find(
                "frame 1: 1 obstacle-intersection; in the step from 0: 2 cloth-vertex-obstacle"),
            std::string::npos)
      << r.text();
}

// Vertices inside a closed obstacle are counted beside the verdict: in the JSON and a text line,
// without making the certificate unclean.
TEST(AuditReport, InsideIsCountedBesideTheVerdict) {
  AuditReport r(square(), {}, 16);
  audit::FrameReport f0, f1;
  f1.frame = 1, f1.has_step = true;
  EXPECT_FALSE(r.add(f0));
  EXPECT_EQ(r.json()["inside"], 0);
  EXPECT_EQ(r.text().find("inside"), std::string::npos);
  f0.inside = 2, f1.inside = 1;
  AuditReport s(square(), {}, 16);
  s.add(f0), s.add(f1);
  EXPECT_TRUE(s.clean());
  EXPECT_EQ(s.json()["inside"], 3);
  EXPECT_EQ(s.json()["violations"], 0);
  EXPECT_NE(s.text().find("3 cloth vertices strictly inside a closed obstacle"), std::string::npos)
      << s.text();
}

TEST(AuditReport, ArraysHaveNoPlacesAndNoCaseFiles) {
  AuditReport r(square(), {}, 16);
  audit::FrameReport f0, f1;
  f1.frame = 1, f1.has_step = true, f1.step.cloth_vertex_obstacle = 1;
  f1.violations = {step_violation(0, 0.5)};
  r.add(f0), r.add(f1);
  const nlohmann::ordered_json j = r.json();
  EXPECT_FALSE(j["first_violation"].contains("places"));
  EXPECT_FALSE(j["first_violation"].contains("case_file"));
  EXPECT_TRUE(r.case_records().empty());
  EXPECT_EQ(r.summary_line().rfind("VIOLATION: 2 frames, 1 step, 1 violation; first: ", 0), 0u);
}

}  // namespace
}  // namespace fdh::verify
