// fdhcert classify: every method side by side on query files.
#include <optional>

#include "commands.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/suite/report.hpp"

namespace fdh::verify {
namespace {

const char* const kClassifyHelp =
    R"(usage: fdhcert classify FILE... [--methods LIST] [--gate K] [--kind vf|ee]
                                [--json] [--per-query OUT.csv] [--check]

Runs the collision methods side by side on every query and prints one row per
method: TP, TN, FP, FN, the queries it does not apply to (n/a) and the mean ns
per query. With several files: one block per file, then the total. Counts are
against the file's truth where a query has one, else against `exact`.

Queries are vertex-face (a point against a triangle) or edge-edge, every vertex
moving linearly over the step. exact, robust and float-cubic take them all;
the paper's methods and linear-system take only static vertex-face queries
(the triangle stands still) and show n/a elsewhere.

FILE                 a native query file (docs/formats.md) or a CCD benchmark
                     CSV (*.csv), whose kind comes from a vertex-face or
                     edge-edge folder in its path, else from --kind.

options:
  --methods LIST     comma-separated methods, printed in that order; default:
                     exact,robust,float-cubic,paper-literal,paper-intended,
                     linear-system
  --gate K           the paper methods say "hit" only if the K-DOP of the sweep
                     BB' overlaps the K-DOP of DEF, as inside the FDH tree
                     (K = 6, 14, 18 or 26)
  --kind vf|ee       the kind of CSV files whose path names no vertex-face or
                     edge-edge folder
  --json             print one JSON object instead of the table:
                     {"queries": N, "static_vf": S, "moving_vf": M,
                      "edge_edge": E, "truth": "file"|"exact"|"mixed",
                      "methods": {"exact": {"tp": .., "tn": .., "fp": ..,
                      "fn": .., "na": .., "ns_per_query": ..}, ...},
                      "gate": K, "files": [{"file": F, <the same counts>}]}
                     with null counts where a method applies to nothing
  --per-query FILE   also write FILE, one CSV row per query: id, truth, each
                     method's verdict (0/1/n/a), then exact's contact kind
                     and earliest contact time (a rational, or lo..hi)
  --check            exit 1 if exact disagrees with a file's truth, or robust
                     with exact, on any query
  -h, --help         this text

Bad input (a malformed line, a wrong count of numbers, a non-number, NaN or
Inf, a rational that is not a double, a missing file) is reported as
FILE:LINE: message, with exit status 2 and no output written.
)";

}  // namespace

int classify_command(const Args& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> files, method_names;
  int gate = 0;
  bool json = false, check = false;
  std::string per_query;
  std::optional<QueryKind> kind;
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kClassifyHelp;
      return 0;
    } else if (a.is("--methods")) {
      method_names = split_list(a.value());
    } else if (a.is("--gate")) {
      gate = int(a.integer(0, 64));
    } else if (a.is("--kind")) {
      const std::string& k = a.value();
      if (k == "vf")
        kind = QueryKind::VertexFace;
      else if (k == "ee")
        kind = QueryKind::EdgeEdge;
      else
        throw UsageError("--kind takes vf or ee, not '" + k + "'");
    } else if (a.is("--json")) {
      json = true;
    } else if (a.is("--per-query")) {
      per_query = a.value();
    } else if (a.is("--check")) {
      check = true;
    } else if (a.is_option()) {
      a.unknown("classify");
    } else {
      files.push_back(a.word());
    }
  }
  if (files.empty()) throw UsageError("classify needs at least one query file");

  const std::vector<Method> methods = methods_named(method_names, gate);

  // Read everything before printing anything.
  std::vector<Query> queries;
  std::vector<FileClassification> per_file;
  std::vector<std::vector<Query>> groups;
  for (const std::string& f : files) {
    std::vector<Query> qs = read_query_file(f, kind);
    if (qs.empty()) continue;
    queries.insert(queries.end(), qs.begin(), qs.end());
    per_file.push_back({f, {}});
    groups.push_back(std::move(qs));
  }
  if (queries.empty()) throw InputError(files.front(), 0, "no query to classify");
  std::vector<Classification> parts;
  for (std::size_t i = 0; i < groups.size(); ++i)
    parts.push_back(per_file[i].c = classify(groups[i], methods));
  const Classification c = join(parts);

  const ReportContext ctx{gate};
  if (!per_query.empty()) write_file_atomically(per_query, per_query_csv(queries, c));
  if (json)
    print_json(out, per_file, c, ctx);
  else
    print_table(out, per_file, c, ctx);

  for (const std::size_t i : c.exact_vs_file)
    err << "fdhcert: exact disagrees with the file's truth at " << queries[i].file << ":"
        << queries[i].line << " (query " << queries[i].id << ")\n";
  std::size_t robust_vs_exact = 0;
  for (const MethodResult& m : c.methods) {
    if (m.name != "robust") continue;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (m.verdict[i] == c.exact[i] || m.verdict[i] == kNotApplicable) continue;
      ++robust_vs_exact;
      err << "fdhcert: robust disagrees with exact at " << queries[i].file << ":" << queries[i].line
          << " (query " << queries[i].id << ")\n";
    }
  }
  const bool failed = !c.exact_vs_file.empty() || robust_vs_exact > 0;
  return check && failed ? 1 : 0;
}

}  // namespace fdh::verify
