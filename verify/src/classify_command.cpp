// fdhcert classify: every method side by side on query files.
#include <optional>

#include "commands.hpp"
#include "fdh/verify/atomic_file.hpp"
#include "fdh/verify/classify.hpp"
#include "fdh/verify/input_error.hpp"
#include "fdh/verify/methods.hpp"
#include "fdh/verify/query_io.hpp"
#include "fdh/verify/report.hpp"

namespace fdh::verify {
namespace {

const char* const kClassifyHelp =
    R"(usage: fdhcert classify FILE... [--methods LIST] [--gate K] [--kind vf|ee]
                                [--json] [--per-query OUT.csv] [--check]

Runs the point-triangle methods side by side on every static vertex-face query
(particle B moves to B' during the step; triangle DEF stands still) and prints
one row per method: TP, TN, FP, FN and the mean ns per query. Counts are
against the file's truth where a query has one, else against `exact`.

FILE                 a native query file (docs/formats.md) or a CCD benchmark
                     CSV (*.csv). Queries with a moving triangle and edge-edge
                     queries are skipped with a note: not supported yet.

options:
  --methods LIST     comma-separated methods, printed in that order; default:
                     exact,robust,paper-literal,paper-intended,linear-system
  --gate K           the paper methods say "hit" only if the K-DOP of the sweep
                     BB' overlaps the K-DOP of DEF, as inside the FDH tree
                     (K = 6, 14, 18 or 26)
  --kind vf|ee       the kind of CSV files whose path names no vertex-face or
                     edge-edge folder
  --json             print one JSON object instead of the table:
                     {"queries": N, "truth": "file"|"exact"|"mixed", "gate": K,
                      "skipped": S, "methods": {"exact": {"tp": .., "tn": ..,
                      "fp": .., "fn": .., "ns_per_query": ..}, ...}}
  --per-query FILE   also write FILE, one CSV row per query: id, truth, each
                     method's verdict (0/1), then exact's contact kind and
                     exact contact time (a rational)
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
  std::vector<Query> all, queries;
  for (const std::string& f : files) {
    std::vector<Query> qs = read_query_file(f, kind);
    all.insert(all.end(), qs.begin(), qs.end());
  }
  std::size_t skipped = 0;
  const Query* first_skipped = nullptr;
  for (const Query& q : all) {
    if (q.is_static_vf()) {
      queries.push_back(q);
    } else if (skipped++ == 0) {
      first_skipped = &q;
    }
  }
  if (skipped)
    err << "fdhcert: note: skipped " << skipped
        << " queries with a moving triangle or edge-edge (first: " << first_skipped->file << ":"
        << first_skipped->line << "): not supported yet\n";
  if (queries.empty())
    throw InputError(files.front(), 0, "no static vertex-face query to classify");

  const Classification c = classify(queries, methods);
  const ReportContext ctx{gate, skipped};
  if (!per_query.empty()) write_file_atomically(per_query, per_query_csv(queries, c));
  if (json)
    print_json(out, c, ctx);
  else
    print_table(out, c, ctx);

  for (const std::size_t i : c.exact_vs_file)
    err << "fdhcert: exact disagrees with the file's truth at " << queries[i].file << ":"
        << queries[i].line << " (query " << queries[i].id << ")\n";
  std::size_t robust_vs_exact = 0;
  for (const MethodResult& m : c.methods) {
    if (m.name != "robust") continue;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (m.verdict[i] == c.exact[i]) continue;
      ++robust_vs_exact;
      err << "fdhcert: robust disagrees with exact at " << queries[i].file << ":" << queries[i].line
          << " (query " << queries[i].id << ")\n";
    }
  }
  const bool failed = !c.exact_vs_file.empty() || robust_vs_exact > 0;
  return check && failed ? 1 : 0;
}

}  // namespace fdh::verify
