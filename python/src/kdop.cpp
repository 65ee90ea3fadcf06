// k-DOPs of point sets: the conservative float k-DOP of fast/ (it contains the exact FDH of the
// points), with its slab directions.
#include "fdh/kdop.hpp"
#include "bindings.hpp"

namespace fdh::python {
namespace {

// (lo, hi, directions): k/2 slabs each; row s of directions is slab s's integer direction d,
// and every point p has lo[s] <= d·p <= hi[s].
py::tuple kdop(const py::object& given, int k) {
  const Points pts = points_of(given, "points");
  if (pts.ndim() != 2 || pts.shape(1) != 3 || pts.shape(0) < 1)
    throw py::value_error("points must be an N×3 array of float64 with N >= 1");
  std::vector<Vec3> p(std::size_t(pts.shape(0)));
  const auto v = pts.unchecked<2>();
  for (py::ssize_t i = 0; i < pts.shape(0); ++i) {
    p[std::size_t(i)] = {v(i, 0), v(i, 1), v(i, 2)};
    if (!std::isfinite(v(i, 0)) || !std::isfinite(v(i, 1)) || !std::isfinite(v(i, 2)))
      throw py::value_error("point " + std::to_string(i) + ": a coordinate is not finite");
  }
  if (!is_valid_k(k)) throw py::value_error("k must be 6, 14, 18 or 26, not " + std::to_string(k));
  const py::ssize_t slabs = k / 2;
  py::array_t<double> lo(slabs), hi(slabs);
  py::array_t<int> dirs({slabs, py::ssize_t(3)});
  auto l = lo.mutable_unchecked<1>(), h = hi.mutable_unchecked<1>();
  auto d = dirs.mutable_unchecked<2>();
  with_k(k, [&](auto kc) {
    constexpr int K = decltype(kc)::value;
    const Kdop<K> b = kdop_of<K>(p.data(), p.size());
    for (int s = 0; s < K / 2; ++s) {
      l(s) = b.lo[std::size_t(s)];
      h(s) = b.hi[std::size_t(s)];
      const Direction& dir = Kdop<K>::direction(s);
      d(s, 0) = dir.x, d(s, 1) = dir.y, d(s, 2) = dir.z;
    }
    return 0;
  });
  return py::make_tuple(lo, hi, dirs);
}

}  // namespace

void add_kdop(py::module_& m) {
  m.def("kdop", &kdop, py::arg("points"), py::arg("k") = 18,
        "The conservative k-DOP (k = 6, 14, 18, 26) of an N×3 point array: (lo, hi, "
        "directions), lo[s] <= d_s·p <= hi[s] for every point, pushed outward past rounding.");
}

}  // namespace fdh::python
