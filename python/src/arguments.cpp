// What Python hands the module, taken only where nothing is changed on the way: coordinates and
// truths as numpy would convert them, but refused where the conversion would answer another
// question than the one asked (docs/python.md "What the module refuses"); paths as str, bytes or
// os.PathLike; and Ctrl-C during a long call.
#include <Python.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "bindings.hpp"

namespace fdh::python {
namespace {

// 2^53: every integer up to it in magnitude is a float64 exactly; 2^53 + 1 is not.
constexpr double kExactIntegers = 9007199254740992.0;

std::string dtype_name(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

// Integers: each must be within 2^53 in magnitude, as int64 or uint64 (numpy's widest).
void check_integers(const py::array& a, const char* what) {
  const bool is_signed = a.dtype().kind() == 'i';
  const py::array wide = is_signed ? py::array(converted(py::array_t<std::int64_t>::ensure(a)))
                                   : py::array(converted(py::array_t<std::uint64_t>::ensure(a)));
  const py::ssize_t n = wide.size();
  const auto limit = std::uint64_t(kExactIntegers);
  for (py::ssize_t i = 0; i < n; ++i) {
    const std::uint64_t magnitude =
        is_signed ? [](std::int64_t v) { return v < 0 ? 0 - std::uint64_t(v) : std::uint64_t(v); }(
                        static_cast<const std::int64_t*>(wide.data())[i])
                  : static_cast<const std::uint64_t*>(wide.data())[i];
    if (magnitude > limit)
      throw py::value_error(std::string(what) + ": the integer " +
                            py::str(wide.attr("flat")[py::int_(i)]).cast<std::string>() +
                            " is beyond 2^53 in magnitude, where float64 would round it; pass "
                            "float64 values you chose (docs/python.md)");
  }
}

}  // namespace

Points points_of(const py::handle& obj, const char* what) {
  const py::array a = py::array::ensure(obj);
  if (!a) throw py::value_error(std::string(what) + " must be an array of numbers");
  switch (a.dtype().kind()) {
    case 'b':
      break;
    case 'i':
    case 'u':
      check_integers(a, what);
      break;
    case 'f':  // float16, float32 and float64 widen exactly; a longer float may not
      if (a.dtype().itemsize() > 8 &&
          py::module_::import("numpy")
              .attr("any")(a.attr("astype")("float64").attr("__ne__")(a))
              .cast<bool>())
        throw py::value_error(std::string(what) + ": a " + dtype_name(a) +
                              " value is not a float64 exactly (docs/python.md)");
      break;
    case 'c':
      throw py::value_error(std::string(what) + ": complex numbers (" + dtype_name(a) +
                            ") are refused: the imaginary part would be dropped");
    default:
      throw py::value_error(std::string(what) + ": " + dtype_name(a) +
                            " is not an array of real numbers");
  }
  return converted(Points::ensure(a));
}

std::vector<std::optional<bool>> truths_of(const py::handle& obj, std::size_t n) {
  std::vector<std::optional<bool>> truths;
  if (obj.is_none()) return truths;
  const py::array a = py::array::ensure(obj);
  if (!a || std::string("biuf").find(a.dtype().kind()) == std::string::npos)
    throw py::value_error("truth must hold one 0 or 1 per query, as numbers");
  // As float64: an integer other than 0 or 1 never becomes 0.0 or 1.0, however large.
  const auto t =
      converted(py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a));
  if (t.ndim() != 1 || std::size_t(t.shape(0)) != n)
    throw py::value_error("truth must hold one 0 or 1 per query");
  for (std::size_t i = 0; i < n; ++i) {
    const double v = t.at(py::ssize_t(i));
    if (v != 0 && v != 1)
      throw py::value_error("truth of query " + std::to_string(i) + " is " +
                            py::str(a.attr("__getitem__")(py::int_(i))).cast<std::string>() +
                            ", not 0 or 1");
    truths.push_back(v == 1);
  }
  return truths;
}

std::string path_of(const py::handle& obj) {
  // os.fsencode takes str, bytes and os.PathLike, and gives the bytes the system uses.
  return py::module_::import("os").attr("fsencode")(obj).cast<py::bytes>().cast<std::string>();
}

void check_signals() {
  const py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

}  // namespace fdh::python
