// The module `fdhcert`: errors become Python exceptions carrying the fdhcert program's messages.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "fdh/io/input_error.hpp"

PYBIND11_MODULE(fdhcert, m) {
  namespace py = pybind11;
  using namespace fdh::python;
  m.doc() =
      "fdhcert: exact-geometry verification of cloth collision detection with FDH (k-DOP) "
      "trees.\nFast and exact decisions over numpy arrays, k-DOPs, classify and scene runs; "
      "see docs/python.md.";
  // Bad input: the message the program prints, "FILE:LINE: message".
  static py::exception<BadInput> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const fdh::verify::InputError& e) {
      input_error(e.what());
    }
  });
  add_queries(m);
  add_toi(m);
  add_kdop(m);
  add_classify(m);
  add_scene(m);
  add_audit(m);
}
