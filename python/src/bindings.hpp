// The parts of the Python module, each registering its functions on the module (one concept a
// file: queries, times of impact, k-DOPs, classify, scenes), and the conversions they share.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <new>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fdh/query.hpp"

namespace fdh::verify {
struct Method;  // fdh/check/registry.hpp
}

namespace fdh::python {

namespace py = pybind11;
using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Bad input, raised in Python as fdhcert.InputError (a ValueError) with the message the fdhcert
// program prints: "FILE:LINE: message". verify::InputError from the readers becomes one too.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void add_queries(py::module_& m);
void add_kdop(py::module_& m);
void add_classify(py::module_& m);
void add_scene(py::module_& m);
void add_toi(py::module_& m);
void add_audit(py::module_& m);

// An N×8×3 array as N queries of `kind` (the order of fdh::Query: vertex-face v f0 f1 f2 at t = 0,
// then at t = 1; edge-edge ea0 ea1 eb0 eb1, then at t = 1), each asking about the minimum
// separation `min_distance` (0: contact). ValueError for another shape, a non-finite coordinate
// (naming the query) or a min_distance that is not finite and >= 0.
std::vector<Query> queries_of(const Points& a, QueryKind kind, double min_distance = 0);

// An array (or anything numpy makes one of) of coordinates as float64, refusing what the
// conversion would change: integers beyond 2^53 in magnitude, complex numbers, floats longer
// than float64 that do not fit, objects. ValueError starting with `what` (arguments.cpp).
Points points_of(const py::handle& obj, const char* what);

// pybind11's array_t::ensure clears the Python error it meets and gives a null array. Between
// number types the one error a conversion can meet is a copy numpy cannot allocate: raised as
// MemoryError (std::bad_alloc) instead of a null array used later.
template <class Array>
Array converted(Array a) {
  if (!a) throw std::bad_alloc();
  return a;
}

// N truths: none for None; else exactly 0 or 1 each (0.7 and 2^32 + 1 are refused).
std::vector<std::optional<bool>> truths_of(const py::handle& obj, std::size_t n);

// A path given as str, bytes or os.PathLike, as the bytes the system takes.
std::string path_of(const py::handle& obj);

// Lets Python act on a signal during a long call (the GIL released): raises
// py::error_already_set (KeyboardInterrupt for Ctrl-C) if a handler raised.
void check_signals();

// How often the long loops call check_signals: every so many queries (about a millisecond).
inline constexpr std::size_t kQueriesPerSignalCheck = 1 << 14;

// ValueError when `min_distance` > 0 and method `m` answers contact only.
void check_answers_min_distance(const verify::Method& m, double min_distance);

// A job's result object (its to_json) as Python dicts, lists and scalars, key order kept: the
// dict `fdhcert ... --json` prints, without JSON text in between (json_values.cpp).
py::object python_value(const nlohmann::ordered_json& j);

// "vertex-face" or "edge-edge"; ValueError naming the choices otherwise.
QueryKind kind_named(const std::string& name);

}  // namespace fdh::python
