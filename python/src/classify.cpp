// classify, as the program does it: files through the fdhcert program itself (in-process), and
// arrays through the same classification and the same JSON, so the tallies are the CLI's.
#include <nlohmann/json.hpp>

#include <optional>

#include "bindings.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/check/query_times.hpp"
#include "fdh/io/query_record.hpp"
#include "fdh/run/classification_output.hpp"
#include "fdh/run/classify_files.hpp"
#include "fdh/run/json_text.hpp"

namespace fdh::python {
namespace {

py::object to_python(const std::string& json_text) {
  return py::module_::import("json").attr("loads")(json_text);
}

// `fdhcert classify --json` on the files, read and classified as the program does
// (run/classify_files.hpp); bad input raises InputError with the program's message.
// With `time`, also "cpu_time", as `classify --time --rounds ROUNDS`.
py::object classify_files(const std::vector<py::object>& paths,
                          const std::vector<std::string>& methods, const std::string& kind,
                          int gate, bool time, int rounds) {
  if (paths.empty()) throw py::value_error("classify needs at least one file");
  std::vector<std::string> files;
  for (const py::object& p : paths) files.push_back(path_of(p));
  if (!kind.empty() && kind != "vf" && kind != "ee")
    throw py::value_error("kind must be 'vf' or 'ee', not '" + kind + "'");
  const std::vector<verify::Method> ms =
      methods.empty() ? verify::all_methods(gate) : verify::select_methods(methods, gate);
  if (rounds < 1 || rounds > 100) throw py::value_error("rounds must be 1 to 100");
  verify::ClassifiedFiles c;
  std::vector<verify::TimeSpread> spreads;
  {
    py::gil_scoped_release release;
    c = verify::classify_files(files, ms, kind);
    if (time)
      spreads =
          verify::time_spreads(verify::time_each_query(verify::queries_of(c.all), ms, rounds), ms);
  }
  nlohmann::ordered_json j = verify::classification_json(c.files, c.total, {gate});
  if (time) j["cpu_time"] = verify::cpu_times_json(spreads, c.all, rounds);
  return to_python(verify::json_line(j, "classify"));
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
  const auto j = verify::classification_json({{"<array>", c}}, c, {});
  return to_python(verify::json_line(j, "classify_arrays"));
}

}  // namespace

void add_classify(py::module_& m) {
  m.def("classify", &classify_files, py::arg("files"),
        py::arg("methods") = std::vector<std::string>{}, py::arg("kind") = "", py::arg("gate") = 0,
        py::arg("time") = false, py::arg("rounds") = 7,
        "`fdhcert classify --json` on query files (native .vf or benchmark .csv): a dict of "
        "tallies per method, in total and per file. kind: 'vf' or 'ee' for CSVs; gate: a k; "
        "time: also 'cpu_time', each method's per-query thread CPU time (median, p90, max), "
        "as `classify --time --rounds ROUNDS`.");
  m.def("classify_arrays", &classify_arrays, py::arg("queries"), py::arg("kind") = "vertex-face",
        py::arg("truth") = py::none(), py::arg("methods") = std::vector<std::string>{},
        "The same tallies for an N×8×3 array of one kind, against `truth` (N zeros and ones) "
        "or, without it, the exact twin.");
}

}  // namespace fdh::python
