// The text `fdhcert simulate` prints (scene_outputs.hpp simulate_text).
#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <string>

#include "fdh/scene/scene_outputs.hpp"

namespace fdh::verify {
namespace {

// The scene, the step, and the time per frame.
void print_simulate_timing(std::ostream& out, const SimulateText& o, const cloth::Scene& scene,
                           const SceneRun& r) {
  const std::size_t n = scene.obstacles.size();
  out << fmt::format("scene {} ({}): {}x{} particles, {} obstacle{} ({} triangles), skin {:g} m\n",
                     scene.name, o.files.scene_path, r.grid, r.grid, n, n == 1 ? "" : "s",
                     o.obstacle_triangles, r.skin);
  out << fmt::format(
      "narrow phase {}, k = {}, {} frames of dt = {:g} s (stable up to {:g} s{})\n\n", o.run.narrow,
      o.run.k, r.frames, r.dt, r.stable_dt,
      r.dt_reduced ? fmt::format("; the scene's {:g} s is above it", scene.dt) : "");
  const double per = r.frames ? 1e3 / r.frames : 0;  // s summed -> ms per frame
  const cloth::FrameTimes& t = r.time;
  out << fmt::format(
      "ms per frame   springs+integration {:.4f}   refit {:.4f}   traversal {:.4f}   narrow "
      "{:.4f}   response {:.4f}{}\n               collision {:.4f}   total {:.4f}\n",
      per * t.springs, per * t.refit, per * t.traversal, per * t.narrow, per * t.response,
      scene.self_collision ? fmt::format("   self {:.4f}", per * t.self) : "", per * t.collision(),
      per * t.total());
}

// A distance measured, or "none" where nothing was.
std::string distance_text(double d) {
  return std::isfinite(d) ? fmt::format("{:.6g} m", d) : "none";
}

// The gaps kept: the smallest distances reached at the end of a frame (float measures).
void print_simulate_gaps(std::ostream& out, const cloth::Scene& scene, const SceneRun& r) {
  out << fmt::format("gaps (float)   obstacles: skin {:g} m, smallest particle distance {}\n",
                     r.skin, distance_text(r.obstacle_distance_min));
  if (scene.self_collision)
    out << fmt::format("               self: distance {:g} m, smallest among the pairs tested {}\n",
                       r.self_gap, distance_text(r.self_distance_min));
}

// The counts, the checks and the files written.
void print_simulate_counts(std::ostream& out, const SimulateText& o, const cloth::Scene& scene,
                           const SceneRun& r) {
  const double frames = r.frames ? r.frames : 1;
  out << fmt::format(
      "counts         {} candidate pairs, {} collisions ({:.1f} and {:.1f} per "
      "frame)\n",
      r.candidates, r.collisions, r.candidates / frames, r.collisions / frames);
  if (o.run.check) {
    out << fmt::format(
        "accuracy       {} false positives, {} false negatives against the exact "
        "test\n",
        r.fp, r.fn);
    out << fmt::format(
        "audit (exact)  {} particles inside, {} cloth triangles meeting an obstacle "
        "triangle, summed over the frames (last frame: {} and {})\n",
        r.audit.inside, r.audit.obstacle_intersections, r.audit_last.inside,
        r.audit_last.obstacle_intersections);
  }
  if (scene.self_collision)
    out << fmt::format(
        "self-collision {} CCD queries, {} contacts; frames resolved by particle stops {}, "
        "by impact zones {} ({} particles), stopped whole {}\n",
        r.self_queries, r.self_hits, r.self_round_frames - r.self_zone_frames, r.self_zone_frames,
        r.self_zone_particles, r.self_stops);
  print_simulate_gaps(out, scene, r);
  if (r.self_audited)
    out << fmt::format(
        "self (exact)   {} pairs of cloth triangles sharing no particle that meet, "
        "summed over the frames\n",
        r.audit.self_intersections);
  if (!o.files.png.empty()) out << "picture        " << o.files.png << "\n";
  if (!o.files.movie.empty() && r.frames > 0) out << "movie          " << o.files.movie << "\n";
  if (!o.files.record.empty()) out << "queries        " << o.files.record << "\n";
  if (!o.files.obj_dir.empty()) out << "frames         " << o.files.obj_dir << "/frame_*.obj\n";
}

}  // namespace

std::string simulate_text(const SimulateText& o, const cloth::Scene& scene, const SceneRun& r) {
  std::ostringstream out;
  print_simulate_timing(out, o, scene, r);
  print_simulate_counts(out, o, scene, r);
  return out.str();
}

}  // namespace fdh::verify
