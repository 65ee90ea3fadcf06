#include "fdh/scene/scene_run.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "fdh/audit/auditor.hpp"
#include "fdh/check/checker.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/inside.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_file.hpp"

namespace fdh::verify {

int bounded_frames(const cloth::Scene& scene, long frames, long particle_frames) {
  const long particles = long(scene.cloth.grid) * scene.cloth.grid;
  return int(std::min({long(scene.frames), frames, std::max(1L, particle_frames / particles)}));
}

TriMesh obstacles_of(const cloth::Scene& scene) {
  TriMesh obstacles;
  for (const auto& o : scene.obstacles) obstacles.append(cloth::obstacle_mesh(o));
  return obstacles;
}

namespace {

// The cloth's triangles and the scene's obstacles, as the audit engine takes them.
audit::Topology audit_topology(const cloth::Scene& scene, const cloth::Simulation& sim) {
  audit::Topology t;
  t.cloth_vertices = sim.cloth().n();
  t.cloth = sim.cloth().triangles();
  const TriMesh obstacles = obstacles_of(scene);
  t.obstacle_vertices = int(obstacles.x.size());
  t.obstacle = obstacles.tris;
  return t;
}

// A scene's obstacles are solids: each must have an inside for the audit's `inside` count (the
// engine skips open pieces, as `fdhcert audit` must; a scene has none).
void check_closed_obstacles(const cloth::Scene& scene) {
  for (std::size_t o = 0; o < scene.obstacles.size(); ++o)
    if (!exact::is_closed_manifold(cloth::obstacle_mesh(scene.obstacles[o])))
      throw std::invalid_argument("obstacle " + std::to_string(o + 1) +
                                  " is not a closed manifold mesh");
}

// Each checked frame on its own, the cloth against itself only when asked; on every core (as
// --threads allows), with the engine's own k, as `fdhcert audit`.
audit::Options frame_audit_options(bool self) {
  audit::Options o;
  o.keep = 0;
  o.steps = false;
  o.self = self;
  return o;
}

// The smallest distance from a particle of x to an obstacle of the scene (float).
double obstacle_distance_min(const cloth::Scene& scene, const std::vector<Vec3>& x) {
  double d = std::numeric_limits<double>::infinity();
  for (const cloth::Obstacle& o : scene.obstacles)
    for (const Vec3& p : x) d = std::min(d, cloth::obstacle_distance(o, p));
  return d;
}

}  // namespace

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
  r.self_gap = scene.self_collision ? scene.self_gap() : 0;

  check_closed_obstacles(scene);
  const Method narrow = select_methods({opt.narrow}).front();
  cloth::Simulation sim(scene, narrow_phase_named(opt.narrow), opt.k, r.dt, &exact::ccd_hit,
                        &exact::ccd_toi);
  r.self_audited = opt.check && (opt.audit_self || scene.self_collision);
  std::optional<audit::Auditor> audit;
  if (opt.check) audit.emplace(audit_topology(scene, sim), frame_audit_options(r.self_audited));
  const std::vector<Vec3> obstacles = obstacles_of(scene).x;  // still: the same every frame
  // The exact audit of the cloth as it ends a checked frame.
  const auto audit_frame = [&](const cloth::Simulation& sim) {
    ++r.audited_frames;
    r.audit_last = audit::counts_of(audit->add_frame(sim.cloth().x(), obstacles));
    r.audit.add(r.audit_last);
  };
  r.energy_start = sim.cloth().energy();
  if (opt.on_start) opt.on_start(sim);
  for (int f = 1; f <= r.frames; ++f) {
    sim.step();
    r.time += sim.times();
    r.candidates += long(sim.queries().size());
    r.collisions += sim.collisions();
    r.self_repulsions += sim.self().repelled;
    r.self_queries += sim.self().queries;
    r.self_hits += sim.self().hits;
    r.self_round_frames += sim.self().rounds > 0;
    r.self_zone_frames += sim.self().zones;
    r.self_zone_particles += sim.self().zone_particles;
    r.self_stops += sim.self().stopped_all;
    r.self_motion += sim.self().motion, r.self_motion_kept += sim.self().kept;
    r.self_distance_min = std::min(r.self_distance_min, sim.self().min_distance);
    r.obstacle_distance_min =
        std::min(r.obstacle_distance_min, obstacle_distance_min(scene, sim.cloth().x()));
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

cloth::Scene read_scene_overridden(const std::string& path, const SceneOverrides& o) {
  cloth::Scene scene = read_scene(path);
  if (o.grid) scene.cloth.grid = o.grid;
  std::string why;
  if (!o.thickness.empty()) scene.thickness = *parse_double(o.thickness, why);  // checked
  if (!o.self.empty()) scene.self_collision = o.self == "on";
  if (o.grid || !o.thickness.empty()) check_scene(scene, path);  // the overrides too
  return scene;
}

}  // namespace fdh::verify
