// The parts of the Python module, each registering its functions on the module (one concept a
// file: queries, times of impact, k-DOPs, classify, scenes), and the conversions they share.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "fdh/query.hpp"

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
// then at t = 1; edge-edge ea0 ea1 eb0 eb1, then at t = 1). ValueError for another shape or a
// non-finite coordinate, naming the query.
std::vector<Query> queries_of(const Points& a, QueryKind kind);

// "vertex-face" or "edge-edge"; ValueError naming the choices otherwise.
QueryKind kind_named(const std::string& name);

}  // namespace fdh::python
