// fdhcert simulate: one scene, frame by frame, timed and checked.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/io/json.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_file.hpp"
#include "fdh/io/scene_output.hpp"
#include "fdh/suite/scene_run.hpp"

namespace fdh::verify {
namespace {

const char* const kSimulateHelp =
    R"(usage: fdhcert simulate SCENE [--grid N] [--frames F] [--narrow METHOD] [--k K]
                         [--thickness T] [--self on|off] [--audit-self] [--obj DIR]
                         [--png FILE] [--record FILE] [--json] [--no-check]

Runs the cloth of SCENE (a .scene file, docs/formats.md; shipped ones are in
corpus/scenes/) among its obstacles, one step of dt per frame: springs and
Euler integration (eqs. 1-3), refit of the cloth's FDH tree with swept leaves,
traversal against the obstacles' tree, the narrow-phase test on every
candidate pair, and the response of eqs. 4-5.

Prints the mean time per frame split into those five parts, the candidate
pairs and collisions, and two checks, both untimed:
  accuracy  every narrow-phase query against the exact point-triangle test
            (false positives and false negatives);
  audit     after every frame, the exact count of cloth particles strictly
            inside an obstacle and of cloth edges crossing an obstacle
            triangle, summed over the frames.

options:
  --grid N          particles per side (default: the scene's)
  --frames F        frames to run (default: the scene's)
  --narrow METHOD   robust (default), exact, paper-intended, paper-literal or
                    linear-system
  --k K             the FDH's k: 6, 14, 18 (default) or 26
  --thickness T     the collision skin in m (default: the scene's; 0 collides
                    with the obstacles' own surfaces, see docs/cloth.md)
  --self on|off     the cloth against itself: moving vertex-face and edge-edge
                    tests with robust CCD among primitives sharing no particle
                    (default: the scene's self_collision, else off)
  --audit-self      count self-crossings (cloth edges through the cloth's own
                    triangles) even without the self-collision pass
  --obj DIR         write DIR/frame_NNNNN.obj for every frame (cloth and
                    obstacles), for Blender or ParaView
  --png FILE        render the last frame to FILE
  --record FILE     write every narrow-phase query of the run to FILE in the
                    native vf format, for `fdhcert classify FILE`
  --json            print one JSON object instead of the text
  --no-check        skip the accuracy count and the audit
  -h, --help        this text

If the scene's dt is above the cloth's stable step (it shrinks as the grid
grows), 0.9 times the stable step is used, and the output says so.
Exit status: 0; 2 for bad input. A scene error names the file and line.
)";

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string general(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

int simulate_command(const Args& args, std::ostream& out, std::ostream&) {
  std::string scene_path, obj_dir, png, record;
  int grid = 0;
  double thickness = -2;  // not given
  int self = -1;          // not given
  bool json = false;
  SceneRunOptions opt;
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kSimulateHelp;
      return 0;
    } else if (a.is("--grid")) {
      grid = int(a.integer(2, 4000));
    } else if (a.is("--frames")) {
      opt.frames = int(a.integer(0, 100000000));
    } else if (a.is("--narrow")) {
      opt.narrow = a.value();
      try {
        narrow_phase_named(opt.narrow);
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--narrow: ") + e.what());
      }
    } else if (a.is("--k")) {
      opt.k = int(a.integer(6, 26));
      if (!is_valid_k(opt.k)) throw UsageError("--k takes 6, 14, 18 or 26");
    } else if (a.is("--thickness")) {
      const std::string& v = a.value();
      std::string why;
      const auto t = parse_double(v, why);
      if (!t || *t < 0) throw UsageError("--thickness takes a length >= 0 in m, not '" + v + "'");
      thickness = *t;
    } else if (a.is("--self")) {
      const std::string& v = a.value();
      if (v != "on" && v != "off") throw UsageError("--self takes on or off, not '" + v + "'");
      self = v == "on";
    } else if (a.is("--audit-self")) {
      opt.audit_self = true;
    } else if (a.is("--obj")) {
      obj_dir = a.value();
    } else if (a.is("--png")) {
      png = a.value();
    } else if (a.is("--record")) {
      record = a.value();
    } else if (a.is("--json")) {
      json = true;
    } else if (a.is("--no-check")) {
      opt.check = false;
    } else if (a.is_option()) {
      a.unknown("simulate");
    } else if (scene_path.empty()) {
      scene_path = a.word();
    } else {
      throw UsageError("simulate takes one scene, not '" + a.word() + "' too");
    }
  }
  if (scene_path.empty()) throw UsageError("simulate needs a scene file (see corpus/scenes/)");
  cloth::Scene scene = read_scene(scene_path);
  if (grid) scene.cloth.grid = grid;
  if (thickness >= 0) scene.thickness = thickness;
  if (self >= 0) scene.self_collision = self == 1;
  if (!obj_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(obj_dir, ec);
    if (ec) throw std::runtime_error(obj_dir + ": cannot create folder: " + ec.message());
  }

  std::vector<TriMesh> obstacles;
  for (const auto& o : scene.obstacles) obstacles.push_back(cloth::obstacle_mesh(o));
  TriMesh all_obstacles;
  for (const auto& m : obstacles) all_obstacles.append(m);
  const std::array<double, 3> cloth_colour = {0.85, 0.25, 0.2}, obstacle_colour = {0.7, 0.7, 0.65};

  std::unique_ptr<AtomicFile> recording;
  if (!record.empty()) recording = std::make_unique<AtomicFile>(record);
  if (recording)
    recording->stream() << "# fdhcert simulate " << scene_path << ": every narrow-phase query\n";
  opt.on_frame = [&](const cloth::Simulation& sim, int frame) {
    if (!obj_dir.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05d.obj", frame);
      write_obj(obj_dir + name,
                {{"cloth", &sim.cloth().x(), &sim.cloth().triangles(), cloth_colour},
                 {"obstacles", &all_obstacles.x, &all_obstacles.tris, obstacle_colour}});
    }
    if (recording) {
      for (const auto& q : sim.queries()) {
        Query r = sim.query(q);
        r.id = "f" + std::to_string(frame) + "p" + std::to_string(q.particle) + "t" +
               std::to_string(q.triangle);
        write_native(recording->stream(), r);
      }
    }
  };
  const SceneRun r = run_scene(scene, opt);
  if (recording) recording->commit();
  if (!png.empty()) {
    const cloth::Cloth shape(scene.cloth);
    write_png(png, {{"cloth", &r.final_x, &shape.triangles(), cloth_colour},
                    {"obstacles", &all_obstacles.x, &all_obstacles.tris, obstacle_colour}});
  }

  const double per = r.frames ? 1e3 / r.frames : 0;  // s summed -> ms per frame
  const cloth::FrameTimes& t = r.time;
  const bool checked = opt.check;
  if (json) {
    out << "{\"scene\": " << json_string(scene.name) << ", \"grid\": " << r.grid
        << ", \"particles\": " << r.particles << ", \"frames\": " << r.frames
        << ", \"narrow\": " << json_string(opt.narrow) << ", \"k\": " << opt.k
        << ", \"dt\": " << general(r.dt) << ", \"stable_dt\": " << general(r.stable_dt)
        << ", \"dt_reduced\": " << (r.dt_reduced ? "true" : "false")
        << ", \"skin\": " << general(r.skin)
        << ", \"ms_per_frame\": {\"springs\": " << general(per * t.springs)
        << ", \"refit\": " << general(per * t.refit)
        << ", \"traversal\": " << general(per * t.traversal)
        << ", \"narrow\": " << general(per * t.narrow)
        << ", \"response\": " << general(per * t.response)
        << ", \"self\": " << general(per * t.self)
        << ", \"collision\": " << general(per * t.collision())
        << ", \"total\": " << general(per * t.total()) << "}, \"candidates\": " << r.candidates
        << ", \"collisions\": " << r.collisions;
    if (checked)
      out << ", \"fp\": " << r.fp << ", \"fn\": " << r.fn << ", \"inside\": " << r.audit.inside
          << ", \"crossing\": " << r.audit.crossing;
    else
      out << ", \"fp\": null, \"fn\": null, \"inside\": null, \"crossing\": null";
    out << ", \"self_collision\": " << (scene.self_collision ? "true" : "false")
        << ", \"self_queries\": " << r.self_queries << ", \"self_hits\": " << r.self_hits
        << ", \"self_stops\": " << r.self_stops << ", \"self_crossing\": ";
    if (r.self_audited)
      out << r.audit.self_crossing;
    else
      out << "null";
    out << ", \"energy_start\": " << general(r.energy_start)
        << ", \"energy_end\": " << general(r.energy_end) << "}\n";
    return 0;
  }
  out << "scene " << scene.name << " (" << scene_path << "): " << r.grid << "x" << r.grid
      << " particles, " << scene.obstacles.size() << " obstacle"
      << (scene.obstacles.size() == 1 ? "" : "s") << " (" << all_obstacles.tris.size()
      << " triangles), skin " << general(r.skin) << " m\n";
  out << "narrow phase " << opt.narrow << ", k = " << opt.k << ", " << r.frames
      << " frames of dt = " << general(r.dt) << " s (stable up to " << general(r.stable_dt) << " s"
      << (r.dt_reduced ? "; the scene's " + general(scene.dt) + " s is above it" : "") << ")\n\n";
  out << "ms per frame   springs+integration " << fixed(per * t.springs, 4) << "   refit "
      << fixed(per * t.refit, 4) << "   traversal " << fixed(per * t.traversal, 4) << "   narrow "
      << fixed(per * t.narrow, 4) << "   response " << fixed(per * t.response, 4)
      << (scene.self_collision ? "   self " + fixed(per * t.self, 4) : std::string())
      << "\n               collision " << fixed(per * t.collision(), 4) << "   total "
      << fixed(per * t.total(), 4) << "\n";
  out << "counts         " << r.candidates << " candidate pairs, " << r.collisions
      << " collisions (" << fixed(r.frames ? double(r.candidates) / r.frames : 0, 1) << " and "
      << fixed(r.frames ? double(r.collisions) / r.frames : 0, 1) << " per frame)\n";
  if (checked) {
    out << "accuracy       " << r.fp << " false positives, " << r.fn
        << " false negatives against the exact test\n";
    out << "audit (exact)  " << r.audit.inside << " particles inside, " << r.audit.crossing
        << " crossing edges, summed over the frames (last frame: " << r.audit_last_inside << " and "
        << r.audit_last_crossing << ")\n";
  }
  if (scene.self_collision)
    out << "self-collision " << r.self_queries << " CCD queries, " << r.self_hits << " contacts, "
        << r.self_stops << " frames stopped whole\n";
  if (r.self_audited)
    out << "self (exact)   " << r.audit.self_crossing
        << " cloth edges through the cloth's own triangles, summed over the frames\n";
  if (!png.empty()) out << "picture        " << png << "\n";
  if (!record.empty()) out << "queries        " << record << "\n";
  if (!obj_dir.empty()) out << "frames         " << obj_dir << "/frame_*.obj\n";
  return 0;
}

}  // namespace fdh::verify
