// classify, as the program does it: files through the classify job itself (in-process), and
// arrays through the same classification and the same output, so the tallies are the CLI's.
#include <nlohmann/json.hpp>

#include <optional>

#include "bindings.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/classify/classification_output.hpp"
#include "fdh/classify/classify.hpp"

namespace fdh::python {
namespace {

// `fdhcert classify --json` on the files, by the classify job (fdh/classify/classify.hpp); bad
// input raises InputError with the program's message, a bad option ValueError (the job's words).
// With `time`, also "cpu_time", as `classify --time --rounds ROUNDS`.
py::object classify_files(const std::vector<py::object>& paths,
                          const std::vector<std::string>& methods, const std::string& kind,
                          int gate, bool time, int rounds, double min_distance) {
  verify::ClassifyOptions o;
  for (const py::object& p : paths) o.files.push_back(path_of(p));
  o.methods = methods, o.kind = kind, o.gate = gate, o.time = time, o.rounds = rounds;
  o.min_distance = min_distance;
  o.validate();  // before the GIL is released: ValueError
  verify::ClassifyResult r;
  {
    py::gil_scoped_release release;
    r = verify::classify_job(o);
  }
  return python_value(r.to_json());
}

// The same tallies for queries held in an array: one "file" named "<array>".
py::object classify_arrays(const py::object& a, const std::string& kind, py::object truth,
                           const std::vector<std::string>& methods) {
  const std::vector<Query> qs = queries_of(points_of(a, "queries"), kind_named(kind));
  const std::vector<std::optional<bool>> truths = truths_of(truth, qs.size());
  const std::vector<verify::Method> ms =
      methods.empty() ? verify::all_methods() : verify::select_methods(methods);
  verify::Classification c;
  {
    py::gil_scoped_release release;
    c = verify::classify(qs, truths, ms);
  }
  return python_value(verify::classification_json({{"<array>", c}}, c, {}));
}

}  // namespace

void add_classify(py::module_& m) {
  m.def("classify", &classify_files, py::arg("files"),
        py::arg("methods") = std::vector<std::string>{}, py::arg("kind") = "", py::arg("gate") = 0,
        py::arg("time") = false, py::arg("rounds") = 7, py::arg("min_distance") = 0.0,
        "`fdhcert classify --json` on query files (native .vf or benchmark .csv): a dict of "
        "tallies per method, in total and per file. kind: 'vertex-face' or 'edge-edge' for CSVs "
        "whose path names neither; gate: a k; time: also 'cpu_time', each method's per-query "
        "thread CPU time (median, p90, max), as `classify --time --rounds ROUNDS`; "
        "min_distance: every query asked at that minimum separation, as `--min-distance`.");
  m.def("classify_arrays", &classify_arrays, py::arg("queries"), py::arg("kind") = "vertex-face",
        py::arg("truth") = py::none(), py::arg("methods") = std::vector<std::string>{},
        "The same tallies for an N×8×3 array of one kind, against `truth` (N zeros and ones) "
        "or, without it, the exact twin.");
}

}  // namespace fdh::python
