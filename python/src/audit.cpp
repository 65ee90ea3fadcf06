// fdhcert.audit: a sequence of mesh frames held in numpy arrays, certified as `fdhcert audit`
// certifies OBJ files, with the same certificate (fdh/run/audit_report.hpp builds both).
#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>

#include "bindings.hpp"
#include "fdh/audit/auditor.hpp"
#include "fdh/run/audit_report.hpp"
#include "fdh/run/json_text.hpp"

namespace fdh::python {
namespace {

using Faces = py::array_t<long long, py::array::c_style | py::array::forcecast>;

std::vector<Tri> faces_of(const Faces& f, py::ssize_t vertices, const char* what) {
  if (f.ndim() != 2 || f.shape(1) != 3)
    throw py::value_error(std::string(what) + " must be an M×3 array of vertex indices");
  std::vector<Tri> out(std::size_t(f.shape(0)));
  const auto v = f.unchecked<2>();
  for (py::ssize_t i = 0; i < f.shape(0); ++i)
    for (py::ssize_t c = 0; c < 3; ++c) {
      const long long x = v(i, c);
      if (x < 0 || x >= vertices)
        throw py::value_error(std::string(what) + " " + std::to_string(i) + ": vertex index " +
                              std::to_string(x) + " is not in [0, " + std::to_string(vertices) +
                              ")");
      out[std::size_t(i)][std::size_t(c)] = int(x);
    }
  return out;
}

// Row `f` of an F×N×3 array (or the N×3 array itself when `a` has two dimensions).
std::vector<Vec3> frame_of(const Points& a, py::ssize_t f) {
  std::vector<Vec3> out;
  if (a.ndim() == 2) {
    const auto v = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i) out.push_back({v(i, 0), v(i, 1), v(i, 2)});
  } else {
    const auto v = a.unchecked<3>();
    for (py::ssize_t i = 0; i < a.shape(1); ++i)
      out.push_back({v(f, i, 0), v(f, i, 1), v(f, i, 2)});
  }
  return out;
}

// The obstacles' vertex count: P×3 (fixed) or F×P×3 (one row per frame).
py::ssize_t obstacle_vertices(const Points& o, py::ssize_t frames) {
  if (o.ndim() == 2 && o.shape(1) == 3) return o.shape(0);
  if (o.ndim() == 3 && o.shape(2) == 3 && o.shape(0) == frames) return o.shape(1);
  throw py::value_error("obstacles must be P×3 (fixed) or F×P×3 with the frames' F");
}

py::object audit(const Points& frames, const Faces& faces, const std::optional<Points>& obstacles,
                 const std::optional<Faces>& obstacle_faces, int k, int threads, int keep) {
  if (frames.ndim() != 3 || frames.shape(2) != 3 || frames.shape(0) < 1)
    throw py::value_error("frames must be an F×N×3 array of float64 with F >= 1");
  if (obstacles.has_value() != obstacle_faces.has_value())
    throw py::value_error("obstacles and obstacle_faces go together");
  audit::Topology t;
  t.cloth_vertices = int(frames.shape(1));
  t.cloth = faces_of(faces, frames.shape(1), "faces");
  if (obstacles) {
    const py::ssize_t p = obstacle_vertices(*obstacles, frames.shape(0));
    t.obstacle_vertices = int(p);
    t.obstacle = faces_of(*obstacle_faces, p, "obstacle_faces");
  }
  audit::Options opt;
  opt.k = k, opt.threads = threads, opt.keep = keep;
  audit::Auditor auditor(t, opt);  // std::invalid_argument: ValueError
  verify::AuditReport report(t, opt, keep);
  const auto start = std::chrono::steady_clock::now();
  for (py::ssize_t f = 0; f < frames.shape(0); ++f) {
    const std::vector<Vec3> x = frame_of(frames, f);
    const std::vector<Vec3> o = obstacles ? frame_of(*obstacles, f) : std::vector<Vec3>{};
    py::gil_scoped_release release;
    report.add(auditor.add_frame(x, o));
  }
  report.finish(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return py::module_::import("json").attr("loads")(verify::json_text(report.json(), "audit"));
}

}  // namespace

void add_audit(py::module_& m) {
  m.def("audit", &audit, py::arg("frames"), py::arg("faces"), py::arg("obstacles") = py::none(),
        py::arg("obstacle_faces") = py::none(), py::arg("k") = 18, py::arg("threads") = 0,
        py::arg("keep") = 16,
        "Certifies a sequence of frames as `fdhcert audit --json` does and returns the same "
        "dict: frames F×N×3 (float64), faces M×3 (indices into a frame's N vertices), "
        "obstacles P×3 (fixed) or F×P×3 (one per frame) with obstacle_faces Q×3. Decides "
        "exactly whether two cloth triangles sharing no vertex intersect or a cloth triangle "
        "meets an obstacle's in a frame, and whether a vertex passes through a triangle or an "
        "edge through an edge during a step (every vertex moving linearly). docs/audit.md.");
}

}  // namespace fdh::python
