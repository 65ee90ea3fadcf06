// The time-of-impact decisions over numpy arrays (fdh/ccd/toi.hpp through the registry): any
// method that gives a time (robust, exact, float-cubic, a plug-in's), as arrays hit, t_lo, t_hi.
#include <tuple>

#include "bindings.hpp"
#include "fdh/check/registry.hpp"

namespace fdh::python {
namespace {

using Times = py::array_t<double>;

// The times of `method` at `width` on every query of `kind` within `min_distance`: (hit, t_lo,
// t_hi), t_lo = t_hi = 1 where it finds none.
std::tuple<py::array_t<bool>, Times, Times> times_of(const py::object& a, const std::string& method,
                                                     double width, QueryKind kind,
                                                     double min_distance) {
  if (!(width > 0 && width <= 1))
    throw py::value_error("width must be in (0, 1], not " + std::to_string(width));
  const std::vector<Query> qs = queries_of(points_of(a, "queries"), kind, min_distance);
  const verify::Method m = verify::select_methods({method}).front();
  check_answers_min_distance(m, min_distance);
  const verify::Decision d =
      kind == QueryKind::EdgeEdge ? verify::Decision::EdgeEdgeToi : verify::Decision::VertexFaceToi;
  const verify::QueryToi& toi = m.toi[verify::toi_index(d)];
  if (!toi) throw py::value_error(method + " gives no time for " + verify::to_string(d));
  const auto n = py::ssize_t(qs.size());
  py::array_t<bool> hit(n);
  Times lo(n), hi(n);
  auto h = hit.mutable_unchecked<1>();
  auto l = lo.mutable_unchecked<1>(), u = hi.mutable_unchecked<1>();
  py::gil_scoped_release release;
  for (py::ssize_t i = 0; i < n; ++i) {
    if (std::size_t(i) % kQueriesPerSignalCheck == kQueriesPerSignalCheck - 1) check_signals();
    const Toi t = toi(qs[std::size_t(i)], width);
    h(i) = t.hit, l(i) = t.t_lo, u(i) = t.t_hi;
  }
  return {hit, lo, hi};
}

}  // namespace

void add_toi(py::module_& m) {
  const struct {
    const char* name;
    QueryKind kind;
    const char* doc;
  } decisions[] = {
      {"vertex_face_toi", QueryKind::VertexFace,
       "The time of impact of a moving point and triangle. N×8×3 → (hit, t_lo, t_hi): N "
       "booleans and two N arrays of step times enclosing the earliest contact, or with "
       "min_distance > 0 the earliest time within that Euclidean distance (1, 1 without "
       "one); robust's enclosure is exact and at most `width` wide."},
      {"edge_edge_toi", QueryKind::EdgeEdge,
       "The time of impact of two moving edges. N×8×3 → (hit, t_lo, t_hi), as vertex_face_toi."}};
  for (const auto& d : decisions)
    m.def(
        d.name,
        [kind = d.kind](const py::object& a, const std::string& method, double width,
                        double min_distance) {
          return times_of(a, method, width, kind, min_distance);
        },
        py::arg("queries"), py::arg("method") = "robust", py::arg("width") = kDefaultToiWidth,
        py::arg("min_distance") = 0.0, d.doc);
}

}  // namespace fdh::python
