// A scene run from Python: the frames as arrays, with the run's summary.
#include <chrono>
#include <optional>
#include <utility>

#include "bindings.hpp"
#include "fdh/scene/simulate_job.hpp"

namespace fdh::python {
namespace {

py::array_t<double> positions_of(const std::vector<Vec3>& x) {
  py::array_t<double> a({py::ssize_t(x.size()), py::ssize_t(3)});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < x.size(); ++i)
    r(py::ssize_t(i), 0) = x[i].x, r(py::ssize_t(i), 1) = x[i].y, r(py::ssize_t(i), 2) = x[i].z;
  return a;
}

py::dict summary_of(const verify::SceneRun& r, bool checked) {
  py::dict s;
  s["grid"] = r.grid, s["frames"] = r.frames, s["particles"] = r.particles, s["dt"] = r.dt;
  s["ms_per_frame"] = r.ms_per_frame(), s["candidates"] = r.candidates;
  s["collisions"] = r.collisions, s["fp"] = r.fp, s["fn"] = r.fn;
  // The exact frame audit (None when not checked): the counts of simulate --json.
  s["inside"] = checked ? py::object(py::int_(r.audit.inside)) : py::object(py::none());
  s["crossing"] =
      checked ? py::object(py::int_(r.audit.obstacle_intersections)) : py::object(py::none());
  s["self_crossing"] =
      r.self_audited ? py::object(py::int_(r.audit.self_intersections)) : py::object(py::none());
  return s;
}

// Runs the scene file (with the overrides the CLI's simulate takes) and keeps every `every`-th
// frame's particle positions: {"positions": F×N×3, "frames": [frame numbers], "triangles":
// M×3, "summary": {...}}.
py::dict simulate(const py::object& scene_path, const std::optional<int>& frames, int grid,
                  int every, const std::string& narrow, int k, bool check) {
  if (every < 1) throw py::value_error("every must be at least 1");
  // As the program's --frames: a count of frames; None (the default) runs the scene's.
  if (frames && *frames < 0)
    throw py::value_error("frames must be 0 or more (None: the scene's), not " +
                          std::to_string(*frames));
  verify::SimulateOptions job;
  job.scene_path = path_of(scene_path);
  job.overrides.grid = grid;
  verify::SceneRunOptions& opt = job.run;
  opt.narrow = narrow, opt.k = k, opt.frames = frames.value_or(-1), opt.check = check;
  std::vector<std::vector<Vec3>> kept;
  std::vector<int> numbers;
  std::vector<Tri> tris;
  auto last_check = std::chrono::steady_clock::now();
  opt.on_frame = [&](const cloth::Simulation& sim, int f) {
    // Ctrl-C acts within a tenth of a second of frames, not when the run ends.
    if (const auto now = std::chrono::steady_clock::now();
        now - last_check > std::chrono::milliseconds(100))
      last_check = now, check_signals();
    if (tris.empty()) tris = sim.cloth().triangles();
    if (f % every == 0) kept.push_back(sim.cloth().x()), numbers.push_back(f);
  };
  verify::SceneRun run;
  {
    py::gil_scoped_release release;
    run = verify::simulate_job(std::move(job)).r;
  }
  const py::ssize_t n = run.particles;
  py::array_t<double> pos({py::ssize_t(kept.size()), n, py::ssize_t(3)});
  auto p = pos.mutable_unchecked<3>();
  for (std::size_t f = 0; f < kept.size(); ++f)
    for (py::ssize_t i = 0; i < n; ++i) {
      const Vec3& x = kept[f][std::size_t(i)];
      p(py::ssize_t(f), i, 0) = x.x, p(py::ssize_t(f), i, 1) = x.y, p(py::ssize_t(f), i, 2) = x.z;
    }
  py::array_t<int> t({py::ssize_t(tris.size()), py::ssize_t(3)});
  auto tr = t.mutable_unchecked<2>();
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (int c = 0; c < 3; ++c) tr(py::ssize_t(i), c) = tris[i][std::size_t(c)];
  py::dict out;
  out["positions"] = pos, out["frames"] = numbers, out["triangles"] = t;
  out["final"] = positions_of(run.final_x), out["summary"] = summary_of(run, check);
  return out;
}

}  // namespace

void add_scene(py::module_& m) {
  m.def("simulate", &simulate, py::arg("scene"), py::arg("frames") = py::none(),
        py::arg("grid") = 0, py::arg("every") = 1, py::arg("narrow") = "robust", py::arg("k") = 18,
        py::arg("check") = false,
        "Runs a cloth scene file: every `every`-th frame's positions (F×N×3), the cloth's "
        "triangles, the last positions and the run's summary (check=True: FP/FN against the "
        "exact test and the exact audit, as simulate prints them).");
}

}  // namespace fdh::python
