// The query decisions over numpy arrays: static point-triangle, vertex-face CCD and edge-edge
// CCD by any method of the registry (robust, exact, float-cubic, ...), and the exact earliest
// contact time.
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/exact/ccd.hpp"

namespace fdh::python {

QueryKind kind_named(const std::string& name) {
  if (name == "vertex-face") return QueryKind::VertexFace;
  if (name == "edge-edge") return QueryKind::EdgeEdge;
  throw py::value_error("kind '" + name + "' is not one of vertex-face, edge-edge");
}

void check_answers_min_distance(const verify::Method& m, double min_distance) {
  if (min_distance > 0 && !m.answers_min_distance)
    throw py::value_error(m.name +
                          " answers contact only, not min_distance > 0 "
                          "(min_distance_methods() lists those that do)");
}

std::vector<Query> queries_of(const Points& a, QueryKind kind, double min_distance) {
  if (!(std::isfinite(min_distance) && min_distance >= 0))
    throw py::value_error("min_distance must be a finite number >= 0, not " +
                          py::repr(py::float_(min_distance)).cast<std::string>());
  if (a.ndim() != 3 || a.shape(1) != 8 || a.shape(2) != 3)
    throw py::value_error("queries must be an N×8×3 array of float64 (8 points per query)");
  std::vector<Query> qs(std::size_t(a.shape(0)));
  const auto v = a.unchecked<3>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    Query& q = qs[std::size_t(i)];
    q.kind = kind;
    q.min_distance = min_distance;
    for (py::ssize_t j = 0; j < 8; ++j) {
      q.x[std::size_t(j)] = {v(i, j, 0), v(i, j, 1), v(i, j, 2)};
      if (!std::isfinite(v(i, j, 0)) || !std::isfinite(v(i, j, 1)) || !std::isfinite(v(i, j, 2)))
        throw py::value_error("query " + std::to_string(i) + ": a coordinate is not finite");
    }
  }
  return qs;
}

namespace {

// The verdicts of `method` on every query, as its decision `d` asks, within `min_distance`.
py::array_t<bool> decide(const py::object& given, const std::string& method, verify::Decision d,
                         double min_distance) {
  const std::vector<Query> qs =
      queries_of(points_of(given, "queries"),
                 d == verify::Decision::EdgeEdgeCcd ? QueryKind::EdgeEdge : QueryKind::VertexFace,
                 min_distance);
  const verify::Method m = verify::select_methods({method}).front();
  const auto& test = m.test[std::size_t(d)];
  check_answers_min_distance(m, min_distance);
  if (!test) throw py::value_error(method + " does not decide " + verify::to_string(d));
  if (d == verify::Decision::PointTriangle)
    for (std::size_t i = 0; i < qs.size(); ++i)
      if (!qs[i].is_static_vf())
        throw py::value_error("query " + std::to_string(i) +
                              ": the triangle moves; use vertex_face_ccd");
  py::array_t<bool> out(py::ssize_t(qs.size()));
  auto r = out.mutable_unchecked<1>();
  py::gil_scoped_release release;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    if (i % kQueriesPerSignalCheck == kQueriesPerSignalCheck - 1) check_signals();
    r(py::ssize_t(i)) = test(qs[i]);
  }
  return out;
}

// {"hit": bool, "time": Fraction or None, "interval": (Fraction, Fraction) or None}
py::dict contact_time(const py::object& given, const std::string& kind) {
  const Points a = points_of(given, "query");
  if (a.ndim() != 2 || a.shape(0) != 8 || a.shape(1) != 3)
    throw py::value_error("contact_time takes one query: an 8×3 array");
  Points one = converted(Points::ensure(a));
  one.resize({py::ssize_t(1), py::ssize_t(8), py::ssize_t(3)});
  const Query q = queries_of(one, kind_named(kind)).front();
  const exact::CcdContact c = exact::ccd(q);
  const py::object fraction = py::module_::import("fractions").attr("Fraction");
  py::dict d;
  d["hit"] = c.hit;
  d["time"] = c.time_exact() ? fraction(c.time_lo) : py::none();
  d["interval"] = c.hit ? py::object(py::make_tuple(fraction(c.time_lo), fraction(c.time_hi)))
                        : py::object(py::none());
  return d;
}

}  // namespace

void add_queries(py::module_& m) {
  m.def(
      "methods", [] { return verify::method_names(); },
      "The query methods of the registry, the exact twin first.");
  m.def(
      "min_distance_methods",
      [] {
        std::vector<std::string> names;
        for (const verify::Method& method : verify::all_methods())
          if (method.answers_min_distance) names.push_back(method.name);
        return names;
      },
      "The query methods that answer a minimum separation min_distance > 0 (the others answer "
      "contact only).");
  // One batched function per query decision.
  const struct {
    const char* name;
    verify::Decision decision;
    const char* doc;
  } decisions[] = {
      {"point_triangle", verify::Decision::PointTriangle,
       "Static vertex-face: does B→B' touch (come within min_distance of) the still triangle "
       "DEF? N×8×3 → N booleans."},
      {"vertex_face_ccd", verify::Decision::VertexFaceCcd,
       "Moving point against moving triangle over the step: contact, or Euclidean distance <= "
       "min_distance at some time. N×8×3 → N booleans."},
      {"edge_edge_ccd", verify::Decision::EdgeEdgeCcd,
       "Two moving edges over the step, as vertex_face_ccd. N×8×3 → N booleans."}};
  for (const auto& d : decisions)
    m.def(
        d.name,
        [decision = d.decision](const py::object& a, const std::string& method,
                                double min_distance) {
          return decide(a, method, decision, min_distance);
        },
        py::arg("queries"), py::arg("method") = "robust", py::arg("min_distance") = 0.0, d.doc);
  m.def("contact_time", &contact_time, py::arg("query"), py::arg("kind") = "vertex-face",
        "The exact earliest contact of one moving query (8×3): hit, the time as a Fraction "
        "when it is rational, and an isolating interval of Fractions.");
}

}  // namespace fdh::python
