// fdhcert classify: every method side by side on query files.
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fdh/check/checker.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/suite/report.hpp"
#include "plugin_option.hpp"

namespace fdh::verify {
namespace {

const char* const kClassifyAbout =
    R"(run the point-triangle methods side by side on query files

Runs the collision methods side by side on every query and prints one row per
method: TP, TN, FP, FN, the queries it does not apply to (n/a) and the mean ns
per query. With several files: one block per file, then the total. Counts are
against the file's truth where a query has one, else against `exact`.

Queries are vertex-face (a point against a triangle) or edge-edge, every vertex
moving linearly over the step. exact, robust and float-cubic take them all;
the paper's methods and linear-system take only static vertex-face queries
(the triangle stands still) and show n/a elsewhere.)";

const char* const kClassifyFooter =
    R"(--json prints one JSON object instead of the table:
  {"queries": N, "static_vf": S, "moving_vf": M, "edge_edge": E,
   "truth": "file"|"exact"|"mixed",
   "methods": {"exact": {"tp": .., "tn": .., "fp": .., "fn": .., "na": ..,
                         "ns_per_query": ..}, ...},
   "gate": K, "files": [{"file": F, <the same counts>}]}
with null counts where a method applies to nothing.

Bad input (a malformed line, a wrong count of numbers, a non-number, NaN or
Inf, a rational that is not a double, a missing file) is reported as
FILE:LINE: message, with exit status 2 and no output written.)";

struct ClassifyOptions {
  std::vector<std::string> files, methods;
  int gate = 0;
  std::string kind;  // "vf", "ee" or "" (from the path)
  bool json = false, check = false;
  std::string per_query;
};

// Every file's queries, read before anything is printed; files without queries are skipped.
struct Inputs {
  std::vector<std::string> files;
  std::vector<std::vector<Query>> groups;
  std::vector<Query> all;
};

Inputs read_inputs(const ClassifyOptions& o) {
  std::optional<QueryKind> kind;
  if (!o.kind.empty()) kind = o.kind == "ee" ? QueryKind::EdgeEdge : QueryKind::VertexFace;
  Inputs in;
  for (const std::string& f : o.files) {
    std::vector<Query> qs = read_query_file(f, kind);
    if (qs.empty()) continue;
    in.all.insert(in.all.end(), qs.begin(), qs.end());
    in.files.push_back(f);
    in.groups.push_back(std::move(qs));
  }
  if (in.all.empty()) throw InputError(o.files.front(), 0, "no query to classify");
  return in;
}

std::string where_and_id(const Query& q) {
  return where(q) + " (query " + q.id + ")";
}

// Prints every disagreement the checker finds: the twin against a file's truth, and each method
// that promises something (registry.hpp) against the twin. Returns how many it found.
std::size_t report_disagreements(const std::vector<Query>& queries,
                                 const std::vector<Method>& methods, const Classification& c,
                                 std::ostream& err) {
  std::string twin = "exact";
  for (const Method& m : all_methods())
    if (m.is_twin) twin = m.name;
  std::size_t found = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const std::optional<bool> agrees = twin_matches_truth(queries[i], c.exact[i]);
    if (!agrees || *agrees) continue;
    ++found;
    err << "fdhcert: " << twin << " disagrees with the file's truth at " << where_and_id(queries[i])
        << "\n";
  }
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const Method& m = methods[k];
    if (m.is_twin || m.promise == Promise::None) continue;
    const std::vector<char>& said = c.methods[k].verdict;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (said[i] == kNotApplicable || keeps_promise(m.promise, said[i], c.exact[i])) continue;
      ++found;
      err << "fdhcert: " << m.name << " disagrees with " << twin << " at "
          << where_and_id(queries[i]) << "\n";
    }
  }
  return found;
}

int run_classify(const ClassifyOptions& o, const Io& io) {
  if (!o.per_query.empty()) check_output_path(o.per_query);
  const std::vector<Method> methods = methods_named(o.methods, o.gate);
  const Inputs in = read_inputs(o);
  std::vector<FileClassification> per_file;
  std::vector<Classification> parts;
  for (std::size_t i = 0; i < in.groups.size(); ++i) {
    parts.push_back(classify(in.groups[i], methods));
    per_file.push_back({in.files[i], parts.back()});
  }
  const Classification c = join(parts);

  const ReportContext ctx{o.gate};
  if (!o.per_query.empty()) write_file_atomically(o.per_query, per_query_csv(in.all, c));
  if (o.json)
    print_json(io.out, classification_json(per_file, c, ctx));
  else
    print_table(io.out, per_file, c, ctx);
  const std::size_t disagreements = report_disagreements(in.all, methods, c, io.err);
  return o.check && disagreements > 0 ? 1 : 0;
}

}  // namespace

Command add_classify(CLI::App& app) {
  auto o = std::make_shared<ClassifyOptions>();
  CLI::App* cmd = add_command(app, "classify", kClassifyAbout, kClassifyFooter);
  cmd->add_option("FILE", o->files,
                  "a native query file (docs/formats.md) or a CCD benchmark\n"
                  "CSV (*.csv), whose kind comes from a vertex-face or\n"
                  "edge-edge folder in its path, else from --kind")
      ->required();
  add_methods_option(*cmd, o->methods,
                     "comma-separated methods, printed in that order; default:\n"
                     "exact,robust,float-cubic,paper-literal,paper-intended,\n"
                     "linear-system");
  cmd->add_option("--gate", o->gate,
                  "the paper methods say \"hit\" only if the K-DOP of the sweep\n"
                  "BB' overlaps the K-DOP of DEF, as inside the FDH tree\n"
                  "(K = 6, 14, 18 or 26)")
      ->type_name("K")
      ->check(kdop_k_validator(true));
  cmd->add_option("--kind", o->kind,
                  "the kind of CSV files whose path names no vertex-face or\n"
                  "edge-edge folder")
      ->check(one_of({"vf", "ee"}))
      ->type_name("vf|ee");
  cmd->add_flag("--json", o->json, "print one JSON object instead of the table (below)");
  cmd->add_option("--per-query", o->per_query,
                  "also write FILE, one CSV row per query: id, truth, each\n"
                  "method's verdict (0/1/n/a), then exact's contact kind\n"
                  "(\"moving\" for a moving query) and earliest contact time\n"
                  "(a rational, or lo..hi)")
      ->type_name("FILE");
  add_plugin_option(*cmd);
  cmd->add_flag("--check", o->check,
                "exit 1 if exact disagrees with a file's truth, or a method\n"
                "that promises exact answers (robust) with exact, on any query");
  return {cmd, [o](const Io& io) { return run_classify(*o, io); }};
}

}  // namespace fdh::verify
