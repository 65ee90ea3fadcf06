// The audit job (verify/audit_job/) over a frame source of its own, and the engine's options the
// scene runs use (Options::steps, Options::self): a spike pushed through a square between
// frames 1 and 2, as in test_auditor.cpp.
#include "fdh/audit_job/audit_job.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "audit_meshes.hpp"
#include "fdh/audit/counts.hpp"

namespace fdh::verify {
namespace {

// A 5 x 5 sheet at z = 1 whose middle vertex (12) goes down to z = -0.5 in frame 2, through
// the square below it at z = 0 (cloth vertices 25 to 28).
std::vector<std::vector<Vec3>> spike_frames(audit::Topology& t) {
  const audit::testing::Mesh b = audit::testing::grid(5, 1.0, {0.03 - 2, 0.01 - 2, 1});
  audit::testing::Mesh a;
  a.x = {{-1.5, -1.5, 0}, {1.5, -1.5, 0}, {1.5, 1.5, 0}, {-1.5, 1.5, 0}};
  a.tris = {{0, 1, 2}, {0, 2, 3}};
  const audit::testing::Mesh m = audit::testing::join(b, a);
  t.cloth_vertices = int(m.x.size());
  t.cloth = m.tris;
  std::vector<Vec3> spiked = m.x;
  spiked[12].z = -0.5;
  return {m.x, m.x, spiked, spiked};
}

// Frames held in memory, as Python's arrays are.
class Frames : public FrameSource {
 public:
  Frames() : x_(spike_frames(t_)) {}
  const audit::Topology& topology() const override { return t_; }
  int frames() const override { return int(x_.size()); }
  MeshFrame read(int i) override {
    MeshFrame m;
    m.index = i;
    m.cloth = x_[std::size_t(i)];
    return m;
  }

 private:
  audit::Topology t_;
  std::vector<std::vector<Vec3>> x_;
};

TEST(AuditJob, OptionsAreCheckedOnce) {
  AuditOptions o;
  EXPECT_NO_THROW(o.validate());
  o.k = 7;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {}, o.threads = -1;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {}, o.keep = 0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  Frames source;
  EXPECT_THROW(run_audit(source, o), std::invalid_argument);
}

TEST(AuditJob, AFrameSourceGivesTheEnginesCertificate) {
  Frames source;
  const AuditResult r = run_audit(source, {});
  // Straight through the engine, frame by frame.
  audit::Topology t;
  const auto x = spike_frames(t);
  audit::Auditor engine(t);
  audit::AuditCounts direct;
  for (const auto& f : x) direct.add(audit::counts_of(engine.add_frame(f, {})));
  EXPECT_GT(direct.step.self_vertex_face, 0);
  EXPECT_GT(direct.self_intersections, 0);
  EXPECT_EQ(r.report().totals().step.self_vertex_face, direct.step.self_vertex_face);
  EXPECT_EQ(r.report().totals().self_intersections, direct.self_intersections);
  EXPECT_EQ(r.exit_status(), 1);
  EXPECT_EQ(r.to_json()["clean"], false);
  EXPECT_NE(r.text().find("VIOLATION"), std::string::npos) << r.text();
}

TEST(AuditJob, TheEngineChecksFramesAloneOrWithoutTheSelfPairsWhenAsked) {
  audit::Topology t;
  const auto x = spike_frames(t);
  audit::Options alone;
  alone.steps = false;  // the scene runs' frames, far apart
  audit::Auditor frames_only(t, alone);
  audit::AuditCounts c;
  for (const auto& f : x) {
    const audit::FrameReport r = frames_only.add_frame(f, {});
    EXPECT_FALSE(r.has_step);
    c.add(audit::counts_of(r));
  }
  EXPECT_EQ(c.step.total(), 0);
  EXPECT_EQ(c.step.candidates, 0);
  EXPECT_GT(c.self_intersections, 0);  // the spike through the square, frames 2 and 3
  audit::Options no_self = alone;
  no_self.self = false;  // a scene without the self-collision pass
  audit::Auditor obstacles_only(t, no_self);
  for (const auto& f : x) EXPECT_EQ(obstacles_only.add_frame(f, {}).self_intersections, 0);
}

}  // namespace
}  // namespace fdh::verify
