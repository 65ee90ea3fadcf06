// fdhcert.audit: a sequence of mesh frames held in numpy arrays, certified as `fdhcert audit`
// certifies OBJ files: the same job (fdh/audit_job/audit_job.hpp) over the arrays, its result's
// certificate as a dict.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <type_traits>

#include "bindings.hpp"
#include "fdh/audit_job/audit_job.hpp"

namespace fdh::python {
namespace {

// Faces of index type T (int64, or uint64 so that 2^64 - 1 is named as it is, not as -1).
template <class T>
std::vector<Tri> faces_as(const py::array& a, py::ssize_t vertices, const char* what) {
  using Faces = py::array_t<T, py::array::c_style | py::array::forcecast>;
  const Faces f = converted(Faces::ensure(a));
  if (f.ndim() != 2 || f.shape(1) != 3)
    throw py::value_error(std::string(what) + " must be an M×3 array of vertex indices");
  if (f.shape(0) == 0)  // as `fdhcert audit` refuses a frame without faces
    throw py::value_error(std::string(what) + ": no faces (M = 0)");
  std::vector<Tri> out(std::size_t(f.shape(0)));
  const auto v = f.template unchecked<2>();
  for (py::ssize_t i = 0; i < f.shape(0); ++i)
    for (py::ssize_t c = 0; c < 3; ++c) {
      const T x = v(i, c);
      bool outside = x >= T(vertices);
      if constexpr (std::is_signed_v<T>) outside = outside || x < 0;
      if (outside)
        throw py::value_error(std::string(what) + " " + std::to_string(i) + ": vertex index " +
                              std::to_string(x) + " is not in [0, " + std::to_string(vertices) +
                              ")");
      out[std::size_t(i)][std::size_t(c)] = int(x);
    }
  return out;
}

// Faces as integers only: a float index (1.5) would be truncated into another face.
std::vector<Tri> faces_of(const py::object& obj, py::ssize_t vertices, const char* what) {
  const py::array a = py::array::ensure(obj);
  if (!a || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
    throw py::value_error(std::string(what) + " must be an M×3 array of integer vertex indices");
  return a.dtype().kind() == 'u' ? faces_as<std::uint64_t>(a, vertices, what)
                                 : faces_as<std::int64_t>(a, vertices, what);
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

// The frames of the arrays, converted one at a time as the job reads them (the GIL taken for
// the conversion only; Ctrl-C acts between frames).
class ArrayFrames : public verify::FrameSource {
 public:
  ArrayFrames(const Points& frames, const std::optional<Points>& obstacles, audit::Topology t)
      : frames_(frames), obstacles_(obstacles), topology_(std::move(t)) {}
  const audit::Topology& topology() const override { return topology_; }
  int frames() const override { return int(frames_.shape(0)); }
  verify::MeshFrame read(int i) override {
    py::gil_scoped_acquire gil;
    check_signals();
    verify::MeshFrame m;
    m.index = i;
    m.cloth = frame_of(frames_, i);
    if (obstacles_) m.obstacle = frame_of(*obstacles_, i);
    return m;
  }

 private:
  const Points& frames_;
  const std::optional<Points>& obstacles_;
  audit::Topology topology_;
};

py::object audit(const py::object& frames_in, const py::object& faces,
                 const py::object& obstacles_in, const py::object& obstacle_faces, int k,
                 int threads, int keep, double min_distance, int near_rings,
                 bool near_first_frame) {
  // Coordinates refused where float64 would change them (arguments.cpp).
  const Points frames = points_of(frames_in, "frames");
  std::optional<Points> obstacles;
  if (!obstacles_in.is_none()) obstacles = points_of(obstacles_in, "obstacles");
  if (frames.ndim() != 3 || frames.shape(2) != 3 || frames.shape(0) < 1)
    throw py::value_error("frames must be an F×N×3 array of float64 with F >= 1");
  if (obstacles.has_value() == obstacle_faces.is_none())
    throw py::value_error("obstacles and obstacle_faces go together");
  audit::Topology t;
  t.cloth_vertices = int(frames.shape(1));
  t.cloth = faces_of(faces, frames.shape(1), "faces");
  if (obstacles) {
    const py::ssize_t p = obstacle_vertices(*obstacles, frames.shape(0));
    t.obstacle_vertices = int(p);
    t.obstacle = faces_of(obstacle_faces, p, "obstacle_faces");
  }
  verify::AuditOptions opt;
  opt.k = k, opt.threads = threads, opt.keep = keep;
  opt.min_distance = min_distance, opt.near_rings = near_rings;
  opt.near_first_frame = near_first_frame;
  ArrayFrames source(frames, obstacles, std::move(t));
  std::optional<verify::AuditResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(verify::run_audit(source, opt));  // std::invalid_argument: ValueError
  }
  return python_value(result->to_json());
}

}  // namespace

void add_audit(py::module_& m) {
  m.def(
      "audit", &audit, py::arg("frames"), py::arg("faces"), py::arg("obstacles") = py::none(),
      py::arg("obstacle_faces") = py::none(), py::arg("k") = 18, py::arg("threads") = 0,
      py::arg("keep") = 16, py::arg("min_distance") = 0.0, py::arg("near_rings") = 2,
      py::arg("near_first_frame") = true,
      "Certifies a sequence of frames as `fdhcert audit --json` does and returns the same "
      "dict: frames F×N×3 (float64), faces M×3 (indices into a frame's N vertices), "
      "obstacles P×3 (fixed) or F×P×3 (one per frame) with obstacle_faces Q×3. Decides "
      "exactly whether two cloth triangles sharing no vertex intersect or a cloth triangle "
      "meets an obstacle's in a frame, and whether a vertex passes through a triangle or an "
      "edge through an edge during a step (every vertex moving linearly). With min_distance D > 0, "
      "also the pairs within distance D without meeting (the proximity kinds; near_rings and "
      "near_first_frame: the rule on pairs near by construction, as --near-rings and "
      "--near-first-frame). docs/audit.md.");
}

}  // namespace fdh::python
