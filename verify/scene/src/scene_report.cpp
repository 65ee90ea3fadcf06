#include "fdh/scene/scene_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "fdh/cloth/cloth.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/io/scene_file.hpp"
#include "fdh/io/scene_output.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/output_folder.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

// Times and energies to six significant digits, as simulate has always printed them.
json times_json(const SceneRun& r) {
  const double per = r.frames ? 1e3 / r.frames : 0;  // s summed -> ms per frame
  const cloth::FrameTimes& t = r.time;
  return {{"springs", six_digits(per * t.springs)},       {"refit", six_digits(per * t.refit)},
          {"traversal", six_digits(per * t.traversal)},   {"narrow", six_digits(per * t.narrow)},
          {"response", six_digits(per * t.response)},     {"self", six_digits(per * t.self)},
          {"collision", six_digits(per * t.collision())}, {"total", six_digits(per * t.total())}};
}

// A distance that exists only when it was measured.
json measured(double d) {
  return std::isfinite(d) ? json(six_digits(d)) : json(nullptr);
}

// A count that exists only when it was counted.
json counted(bool yes, long n) {
  return yes ? json(n) : json(nullptr);
}

}  // namespace

// The share of the stopped particles' motion that the self-collision response kept; null
// where it stopped none.
json motion_kept(const SceneRun& r) {
  return r.self_motion > 0 ? json(r.self_motion_kept / r.self_motion) : json();
}

json scene_run_json(const cloth::Scene& scene, const SceneRunOptions& opt, const SceneRun& r) {
  return {{"scene", scene.name},
          {"grid", r.grid},
          {"particles", r.particles},
          {"frames", r.frames},
          {"narrow", opt.narrow},
          {"k", opt.k},
          {"dt", six_digits(r.dt)},
          {"stable_dt", six_digits(r.stable_dt)},
          {"dt_reduced", r.dt_reduced},
          {"skin", six_digits(r.skin)},
          {"ms_per_frame", times_json(r)},
          {"candidates", r.candidates},
          {"collisions", r.collisions},
          {"fp", counted(opt.check, r.fp)},
          {"fn", counted(opt.check, r.fn)},
          {"inside", counted(opt.check, r.audit.inside)},
          {"crossing", counted(opt.check, r.audit.obstacle_intersections)},
          {"self_collision", scene.self_collision},
          {"self_queries", r.self_queries},
          {"self_hits", r.self_hits},
          {"self_round_frames", r.self_round_frames},
          {"self_zone_frames", r.self_zone_frames},
          {"self_zone_particles", r.self_zone_particles},
          {"self_stops", r.self_stops},
          {"self_motion_kept", motion_kept(r)},
          {"self_crossing", counted(r.self_audited, r.audit.self_intersections)},
          {"self_distance", six_digits(r.self_gap)},
          {"self_repulsions", r.self_repulsions},
          {"self_distance_min", measured(r.self_distance_min)},
          {"obstacle_distance_min", measured(r.obstacle_distance_min)},
          {"energy_start", six_digits(r.energy_start)},
          {"energy_end", six_digits(r.energy_end)}};
}

namespace {

const std::array<double, 3> kCloth = {0.85, 0.25, 0.2}, kObstacles = {0.7, 0.7, 0.65};

}  // namespace

void write_scene_png(const std::string& path, const cloth::Scene& scene, const SceneRun& run) {
  const TriMesh obstacles = obstacles_of(scene);
  const cloth::Cloth shape(scene.cloth);
  write_png(path, {{"cloth", &run.final_x, &shape.triangles(), kCloth},
                   {"obstacles", &obstacles.x, &obstacles.tris, kObstacles}});
}

SceneMovie::SceneMovie(const cloth::Scene& scene, int frames_in_run, int movie_frames)
    : obstacles_(obstacles_of(scene)),
      stride_(std::max(1, frames_in_run / std::max(1, movie_frames))),
      movie_(400, 300, 16) {}

void SceneMovie::frame(const cloth::Simulation& sim, int frame) {
  if (frame != 1 && frame % stride_ != 0) return;
  movie_.add_frame({{"cloth", &sim.cloth().x(), &sim.cloth().triangles(), kCloth},
                    {"obstacles", &obstacles_.x, &obstacles_.tris, kObstacles}});
}

void SceneMovie::write(const std::string& path) const {
  movie_.write(path);
}

std::vector<std::string> scene_files(const std::string& dir) {
  std::error_code ec;  // a link loop is named as one, not as the raw filesystem error
  if (!fs::is_directory(dir, ec))
    throw InputError(dir, 0,
                     ec && ec != std::errc::no_such_file_or_directory
                         ? "cannot be read: " + ec.message()
                         : std::string("not a folder of scenes"));
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".scene") files.push_back(e.path().string());
  if (ec) throw InputError(dir, 0, "cannot list the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

namespace {

// One scene of run_scene_folder: run, then written into `into` (the files named as in `out_dir`).
SceneFolderRun run_one_scene(const std::string& file, const std::string& out_dir,
                             const std::string& into, const SceneFolderOptions& opt) {
  SceneFolderRun r;
  r.file = file;
  r.scene = read_scene(r.file);
  std::optional<SceneMovie> movie;
  if (opt.movies) movie.emplace(r.scene, r.scene.frames);
  r.options.on_frame = [&](const cloth::Simulation& sim, int f) {
    if (movie) movie->frame(sim, f);
    report(opt.progress, {"scenes: " + r.scene.name, f, r.scene.frames, "frames"});
  };
  r.run = run_scene(r.scene, r.options);
  r.options.on_frame = nullptr;
  const std::string stem = fs::path(file).stem().string();
  const auto named = [&](const std::string& tail) {
    return (fs::path(out_dir) / (stem + tail)).string();
  };
  const auto written = [&](const std::string& tail) {
    return (fs::path(into) / (stem + tail)).string();
  };
  if (movie) movie->write(written("-movie.png")), r.movie = named("-movie.png");
  r.png = named(".png");
  r.json = named(".json");
  write_scene_png(written(".png"), r.scene, r.run);
  write_file_atomically(written(".json"),
                        json_text(scene_run_json(r.scene, r.options, r.run), r.json));
  if (opt.done) opt.done(r);
  return r;
}

}  // namespace

std::vector<SceneFolderRun> run_scene_folder(const std::string& scene_dir,
                                             const std::string& out_dir,
                                             const SceneFolderOptions& opt) {
  const std::vector<std::string> files = scene_files(scene_dir);
  for (const std::string& file : files) (void)read_scene(file);  // every scene before any run
  std::vector<std::string> outputs;
  for (const std::string& file : files) {
    const std::string stem = fs::path(file).stem().string();
    outputs.insert(outputs.end(), {stem + ".png", stem + ".json"});
    if (opt.movies) outputs.push_back(stem + "-movie.png");
  }
  check_output_folder(out_dir, outputs);  // before any scene runs
  OutputFolder out(out_dir, outputs);     // published whole: issue 34
  std::vector<SceneFolderRun> runs;
  out.publish([&](const std::string& into) {
    for (const std::string& file : files) runs.push_back(run_one_scene(file, out_dir, into, opt));
  });
  return runs;
}

std::string scene_summary_line(const SceneFolderRun& r) {
  const SceneRun& s = r.run;
  return fmt::format(
      "{:<14} {:>3}x{:<3} {:>5} frames {:>8.4f} ms/frame  FP {} FN {}  inside {} crossing {} "
      "self-crossing {}",
      r.scene.name, s.grid, s.grid, s.frames, s.ms_per_frame(), s.fp, s.fn, s.audit.inside,
      s.audit.obstacle_intersections,
      s.self_audited ? std::to_string(s.audit.self_intersections) : "-");
}

}  // namespace fdh::verify
