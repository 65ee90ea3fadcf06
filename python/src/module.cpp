// The module `fdhcert`: errors become Python exceptions carrying the fdhcert program's messages.
#include <pybind11/pybind11.h>

#include <sstream>

#include "bindings.hpp"
#include "fdh/cli/cli.hpp"
#include "fdh/io/input_error.hpp"

namespace fdh::python {
namespace {

// The program itself, in-process: (exit status, standard output, standard error).
py::tuple run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  int status = 0;
  {
    py::gil_scoped_release release;
    status = verify::run_cli(args, out, err);
  }
  return py::make_tuple(status, out.str(), err.str());
}

}  // namespace
}  // namespace fdh::python

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
  m.def("cli", &run, py::arg("args"),
        "Runs the fdhcert program in-process: (exit status, stdout, stderr).");
  add_queries(m);
  add_kdop(m);
  add_classify(m);
  add_scene(m);
}
