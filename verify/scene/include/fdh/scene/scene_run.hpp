// Runs a scene frame by frame with a chosen narrow phase and k, and checks it: every
// narrow-phase query against the exact point–triangle test (FP, FN), and every checked frame
// against the exact frame audit (the audit engine, fdh/audit/auditor.hpp: cloth particles
// strictly inside an obstacle, cloth triangles that meet an obstacle triangle or, when asked,
// another cloth triangle sharing no particle). Every obstacle must be a closed manifold mesh.
// Shared by `simulate`, `scenes`, `table1` and Python's fdhcert.simulate.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "fdh/audit/counts.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/cloth/simulation.hpp"
#include "fdh/mesh.hpp"

namespace fdh::verify {

struct SceneRunOptions {
  std::string narrow = "robust";
  int k = 18;
  int frames = -1;    // < 0: the scene's
  bool check = true;  // FP/FN and the audit (untimed)
  // Audit the cloth against itself too (every checked frame). On by default when the scene
  // runs the self-collision pass.
  bool audit_self = false;
  // Called once before the first step, with the scene's initial state (frame 0), e.g. to write
  // it as an OBJ (an audit of the frames then covers the first step too).
  std::function<void(const cloth::Simulation&)> on_start;
  // Called after every frame (1-based), e.g. to write an OBJ or record the queries.
  std::function<void(const cloth::Simulation&, int frame)> on_frame;
};

struct SceneRun {
  int grid = 0, frames = 0, particles = 0;
  double dt = 0, stable_dt = 0, skin = 0;
  bool dt_reduced = false;  // the scene's Δt was above stable_dt, so 0.9·stable_dt was used
  cloth::FrameTimes time;   // summed over the frames, s
  long candidates = 0, collisions = 0, fp = 0, fn = 0;
  long broken = 0;  // narrow-phase verdicts that break the method's promise (checker.hpp)
  // The frame audit, each checked frame on its own (no steps: checked frames may be far apart):
  // inside and obstacle_intersections, and self_intersections when self_audited.
  audit::AuditCounts audit;       // summed over the checked frames
  audit::AuditCounts audit_last;  // the last checked frame's
  long audited_frames = 0;  // checked: every frame, or the scene's audit_every-th and the last
  bool self_audited = false;
  // The self-collision pass: its queries and contacts, and how often each stage of its response
  // ended a frame (fdh/cloth/self_collision.hpp): frames whose contacts took particle stops,
  // frames that needed impact zones (and their particles, summed), frames stopped whole.
  long self_repulsions = 0;  // pairs the pass's repulsion slowed, summed over the frames
  long self_queries = 0, self_hits = 0, self_round_frames = 0, self_zone_frames = 0,
       self_zone_particles = 0, self_stops = 0;
  // The motion of the particles whose end of step the response changed, summed over the frames
  // (lengths), and what the response kept of it (stage 1 stops them at their time of impact).
  double self_motion = 0, self_motion_kept = 0;
  // The gaps kept, m: the self-collision pass's (the scene's self distance; 0 without the pass)
  // and the skin. The smallest distances reached at the end of a frame, cheap float measures
  // (infinite when nothing was measured): self, among the pairs the pass tested (its
  // Result::min_distance); obstacle, from any particle to any obstacle's solid (the sphere
  // itself, not its triangles: cloth::obstacle_distance; negative inside).
  double self_gap = 0;
  double self_distance_min = std::numeric_limits<double>::infinity();
  double obstacle_distance_min = std::numeric_limits<double>::infinity();
  double energy_start = 0, energy_end = 0;
  std::vector<Vec3> final_x;  // the cloth's particles after the last frame

  double ms_per_frame() const { return frames ? 1e3 * time.total() / frames : 0; }
};

// The scene's obstacles as one triangle mesh.
TriMesh obstacles_of(const cloth::Scene& scene);

SceneRun run_scene(const cloth::Scene& scene, const SceneRunOptions& opt);

// What a run may change of its scene (simulate --grid, --thickness, --self); 0 or "": the
// scene's own.
struct SceneOverrides {
  int grid = 0;
  std::string thickness;  // a number as query files write it (checked before: parse_double)
  std::string self;       // "on" or "off"
};
// The scene read from `path` (read_scene) with `o` applied, checked again when the grid or the
// thickness changed (check_scene: an InputError naming `path`).
cloth::Scene read_scene_overridden(const std::string& path, const SceneOverrides& o);

// The frames a bounded run of `scene` takes: its own, at most `frames`, and at most
// `particle_frames` / particles, so that a large cloth (a 200x200 one costs 64 times a 25x25
// one per frame) does not swamp a quick check.
int bounded_frames(const cloth::Scene& scene, long frames, long particle_frames);

}  // namespace fdh::verify
