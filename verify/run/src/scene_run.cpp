#include "fdh/run/scene_run.hpp"

#include <algorithm>
#include <stdexcept>

#include "fdh/check/checker.hpp"
#include "fdh/exact/ccd.hpp"

namespace fdh::verify {

int bounded_frames(const cloth::Scene& scene, long frames, long particle_frames) {
  const long particles = long(scene.cloth.grid) * scene.cloth.grid;
  return int(std::min({long(scene.frames), frames, std::max(1L, particle_frames / particles)}));
}

SceneRun run_scene(const cloth::Scene& scene, const SceneRunOptions& opt) {
  SceneRun r;
  const cloth::Cloth probe(scene.cloth);
  r.grid = scene.cloth.grid;
  r.particles = probe.n();
  r.stable_dt = probe.stable_dt();
  r.dt = scene.dt;
  if (r.dt > r.stable_dt) r.dt = 0.9 * r.stable_dt, r.dt_reduced = true;
  r.skin = scene.skin();
  r.frames = opt.frames >= 0 ? opt.frames : scene.frames;

  const Method narrow = select_methods({opt.narrow}).front();
  cloth::Simulation sim(scene, narrow_phase_named(opt.narrow), opt.k, r.dt, &exact::ccd_hit,
                        &exact::ccd_toi);
  r.self_audited = opt.check && (opt.audit_self || scene.self_collision);
  std::vector<TriMesh> obstacles;
  for (const auto& o : scene.obstacles) obstacles.push_back(cloth::obstacle_mesh(o));
  const exact::Audit audit(obstacles);
  // The exact audit of the cloth as it ends a checked frame.
  const auto audit_frame = [&](const cloth::Simulation& sim) {
    ++r.audited_frames;
    exact::AuditCounts c = audit.count(sim.cloth().x(), sim.cloth().edges());
    if (r.self_audited)
      c.self_crossing =
          exact::self_crossings(sim.cloth().x(), sim.cloth().edges(), sim.cloth().triangles());
    r.audit += c;
    r.audit_last_inside = c.inside, r.audit_last_crossing = c.crossing;
  };
  r.energy_start = sim.cloth().energy();
  if (opt.on_start) opt.on_start(sim);
  for (int f = 1; f <= r.frames; ++f) {
    sim.step();
    r.time += sim.times();
    r.candidates += long(sim.queries().size());
    r.collisions += sim.collisions();
    r.self_queries += sim.self().queries;
    r.self_hits += sim.self().hits;
    r.self_round_frames += sim.self().rounds > 0;
    r.self_zone_frames += sim.self().zones;
    r.self_zone_particles += sim.self().zone_particles;
    r.self_stops += sim.self().stopped_all;
    r.self_motion += sim.self().motion, r.self_motion_kept += sim.self().kept;
    if (opt.check && (f % scene.audit_every == 0 || f == r.frames)) {  // the scene's stride
      for (const auto& nq : sim.queries()) {
        const Verdicts v = check_given(narrow, sim.query(nq), nq.hit);
        r.fp += v.said && !v.twin;
        r.fn += !v.said && v.twin;
        r.broken += !v.kept;
      }
      audit_frame(sim);
    }
    if (opt.on_frame) opt.on_frame(sim, f);
  }
  r.energy_end = sim.cloth().energy();
  r.final_x = sim.cloth().x();
  return r;
}

}  // namespace fdh::verify
