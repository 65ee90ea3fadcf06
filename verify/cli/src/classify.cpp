// fdhcert classify: every method side by side on query files.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fdh/check/checker.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/check/query_times.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/record_scope.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/run/classification_output.hpp"
#include "fdh/run/classify_files.hpp"
#include "fdh/run/toi_report.hpp"
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
(the triangle stands still) and show n/a elsewhere.

On standard error, every disagreement of a method that promises something with
exact, in the checker's words: which promise it breaks, as in
  aabb misses a hit at FILE:LINE (query ID) (breaks CONSERVATIVE)
or that its promise allows it (the first 10 per method, the rest counted), as in
  aabb gives a false alarm at FILE:LINE (query ID) (allowed: conservative)
and every place exact disagrees with a file's truth.

Exit status: 0 when the table is printed, whatever the methods answer; 1 only
with --check, where exact disagrees with a file's truth or a promise breaks
(an allowed disagreement never counts); 2 for bad input or options.)";

const char* const kClassifyFooter =
    R"(--json prints one JSON object instead of the table:
  {"queries": N, "static_vf": S, "moving_vf": M, "edge_edge": E,
   "truth": "file"|"exact"|"mixed",
   "methods": {"exact": {"tp": .., "tn": .., "fp": .., "fn": .., "na": ..,
                         "ns_per_query": .., "promise": "exact",
                         "against_exact": {"misses": .., "false_alarms": ..,
                                           "broken": .., "allowed": ..}}, ...},
   "gate": K, "files": [{"file": F, <the same counts>}]}
with null counts where a method applies to nothing; against_exact counts the
method's answers against exact (not the file's truth) by direction, and how
many break its promise or are allowed by it. With --toi it also holds
  "toi": {"width": W, "methods": {"robust": {"promise": "exact-enclosure",
          "checked": .., "contacts": .., "late": .., "zero": .., "verdict_errors": ..,
          "not_enclosed": .., "too_wide": .., "broken": .., "early_max": ..,
          "early_median": .., "toi_ns_per_query": .., "na": ..}, ...},
          "files": [{"file": F, "methods": {...}}]}
for the methods that give a time (exact, robust, float-cubic, plug-ins of ABI
version 2): late counts a contact missed or a t_lo after the exact earliest
contact t*; zero a t_lo of 0 where t* > 0; early is t* - t_lo in step units.
With --time it also holds
  "cpu_time": {"rounds": R, "methods": {"robust": {"queries": .., "median_ns": ..,
               "p90_ns": .., "max_ns": .., "slowest": WHERE}, ...}}
each method's thread CPU time per query over the queries it applies to, each
query timed alone (the least disturbed of --rounds batches, a batch long enough
for the clock). With --time-ratio BASE it
also holds
  "time_ratio": {"to": BASE, "limit": R, "queries": N,
                 "mean_ns": {"robust": .., "exact": ..}, "methods": {"robust":
                 {"vertex-face-ccd": {"queries": .., "max": .., "median": ..,
                  "worst": WHERE, "over_limit": ..}, ...}, ...}}
each method's time over BASE's, query by query (each query timed alone), per
query decision (point-triangle, vertex-face-ccd, edge-edge-ccd), and each
method's mean of those times (thread CPU time: unlike the table's ns/query, not
inflated by waiting for a core on a busy machine).

Bad input (a malformed line, a wrong count of numbers, a non-number, NaN or
Inf, a rational that is not a double, a missing file) is reported as
FILE:LINE: message, with exit status 2 and no output written.)";

struct ClassifyOptions {
  std::vector<std::string> files, methods;
  int gate = 0;
  std::string kind;  // "vf", "ee" or "" (from the path)
  bool json = false, check = false;
  std::string per_query;
  std::string time_ratio;  // a base method: per-query time ratios to it
  double ratio_limit = 1.1;
  int rounds = 7;
  bool toi = false;   // also the times of impact
  bool time = false;  // also each method's per-query thread CPU time: median, p90, maximum
  double width = kDefaultToiWidth;
};

std::string where_and_id(const QueryRecord& q) {
  return where(q) + " (query " + q.id + ")";
}

// How many of a method's allowed disagreements (a conservative method's false alarms) classify
// names one by one; the rest are counted in one line (and in the table's FP).
constexpr std::size_t kAllowedNamed = 10;

// The twin against each file's truth. Returns how many disagree.
std::size_t report_twin_vs_truth(const std::vector<QueryRecord>& queries, const Classification& c,
                                 std::ostream& err) {
  std::string twin = "exact";
  for (const Method& m : all_methods())
    if (m.is_twin) twin = m.name;
  std::size_t found = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const std::optional<bool> agrees = twin_matches_truth(stated(queries[i].truth), c.exact[i]);
    if (!agrees || *agrees) continue;
    ++found;
    err << "fdhcert: " << twin << " disagrees with the file's truth at " << where_and_id(queries[i])
        << "\n";
  }
  return found;
}

// One promised method against the twin, in the checker's words: every broken promise, and the
// first kAllowedNamed disagreements its promise allows. Returns how many promises broke.
std::size_t report_method(const std::vector<QueryRecord>& queries, const Method& m,
                          const std::vector<char>& said, const Classification& c,
                          std::ostream& err) {
  std::size_t broken = 0, allowed = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (said[i] == kNotApplicable) continue;
    const Judgement j = judge(m.promise, said[i], c.exact[i]);
    if (j == Judgement::Kept) continue;
    const bool named = j == Judgement::Broken || allowed < kAllowedNamed;
    (j == Judgement::Broken ? broken : allowed) += 1;
    if (named)
      err << "fdhcert: " << verdict_words(m, said[i], c.exact[i], where_and_id(queries[i])) << "\n";
  }
  if (allowed > kAllowedNamed)
    err << "fdhcert: " << m.name << ": " << allowed - kAllowedNamed
        << " more disagreements with exact " << judgement_words(Judgement::Allowed, m.promise)
        << ", counted in the table\n";
  return broken;
}

// Prints what the checker finds: the twin against a file's truth, and each method that promises
// something (registry.hpp) against the twin, saying which promise broke and which disagreement
// it allows. Returns how many truths and promises broke.
std::size_t report_disagreements(const std::vector<QueryRecord>& queries,
                                 const std::vector<Method>& methods, const Classification& c,
                                 std::ostream& err) {
  std::size_t found = report_twin_vs_truth(queries, c, err);
  for (std::size_t k = 0; k < methods.size(); ++k)
    if (!methods[k].is_twin && methods[k].promise != Promise::None)
      found += report_method(queries, methods[k], c.methods[k].verdict, c, err);
  return found;
}

// Prints every time of impact that breaks its method's TimePromise, in the checker's words
// (checker.hpp: judged_time_words). Returns how many.
std::size_t report_broken_times(const std::vector<QueryRecord>& queries,
                                const std::vector<Method>& methods, const ToiClassification& toi,
                                std::ostream& err) {
  std::size_t found = 0;
  for (const ToiResult& r : toi.methods) {
    if (r.tally.broken == 0) continue;
    found += std::size_t(r.tally.broken);
    for (const Method& m : methods)
      if (m.name == r.name)
        for (const std::size_t i : r.tally.first_broken)
          err << "fdhcert: at " << where_and_id(queries[i]) << ": "
              << judged_time_words(
                     m, check_time_given(m, queries[i].query, toi.width, r.said[i], toi.twin[i]))
              << "\n";
  }
  return found;
}

// Every query timed alone (query_times.hpp), for --time and --time-ratio: the selected methods,
// then --time-ratio's base where it is not among them.
struct QueryTimings {
  std::vector<Method> methods;
  std::vector<std::vector<double>> ns;  // ns[m][i]
  std::size_t base = 0;                 // --time-ratio's base in methods
};

QueryTimings time_queries(const ClassifyOptions& o, const std::vector<QueryRecord>& records,
                          std::vector<Method> methods) {
  const std::vector<Query> qs = queries_of(records);
  const RecordScope asking(records, qs);  // a plug-in's crash names FILE:LINE
  std::size_t base = methods.size();
  for (std::size_t m = 0; m < methods.size(); ++m)
    if (methods[m].name == o.time_ratio) base = m;
  if (!o.time_ratio.empty() && base == methods.size())
    methods.push_back(methods_named({o.time_ratio}, o.gate).front());
  QueryTimings t{std::move(methods), {}, base};
  t.ns = time_each_query(qs, t.methods, o.rounds);
  return t;
}

// Each method's time over the base's, query by query: printed, and returned for --json.
nlohmann::ordered_json print_time_ratios(const ClassifyOptions& o,
                                         const std::vector<QueryRecord>& records,
                                         const QueryTimings& t, std::ostream& out) {
  const std::vector<Query> qs = queries_of(records);
  const auto& times = t.ns;
  const auto& methods = t.methods;
  nlohmann::ordered_json j{{"to", o.time_ratio}, {"limit", o.ratio_limit}, {"queries", qs.size()}};
  j["methods"] = nlohmann::ordered_json::object();
  // Each method's mean over the queries it applies to, each timed alone.
  j["mean_ns"] = nlohmann::ordered_json::object();
  for (std::size_t m = 0; m < methods.size(); ++m) {
    double sum = 0;
    std::size_t n = 0;
    for (const double x : times[m]) sum += x, n += x > 0;
    j["mean_ns"][methods[m].name] = n ? sum / double(n) : 0;
    if (!o.json)
      out << fmt::format("{}: {:.1f} ns per query, the mean of each query timed alone\n",
                         methods[m].name, n ? sum / double(n) : 0);
  }
  for (const TimeRatio& r : time_ratios(qs, times, methods, t.base, o.ratio_limit)) {
    if (r.method == o.time_ratio) continue;
    const std::string worst = where_and_id(records[r.worst]);
    j["methods"][r.method][to_string(r.decision)] = {{"queries", r.queries},
                                                     {"max", r.max},
                                                     {"median", r.median},
                                                     {"worst", worst},
                                                     {"over_limit", r.over}};
    if (!o.json)
      out << fmt::format(
          "{} / {} time per {} query ({}): max {:.3f} at {}, median {:.3f}, {} above {}\n",
          r.method, o.time_ratio, to_string(r.decision), r.queries, r.max, worst, r.median, r.over,
          o.ratio_limit);
  }
  return j;
}

// --time and --time-ratio, from one timing of every query: printed, or added to j for --json.
void report_query_times(const ClassifyOptions& o, const std::vector<QueryRecord>& records,
                        const std::vector<Method>& methods, nlohmann::ordered_json& j,
                        std::ostream& out) {
  if (!o.time && o.time_ratio.empty()) return;
  const QueryTimings t = time_queries(o, records, methods);
  if (o.time) {
    // The selected methods only: --time-ratio's base may have been added after them.
    const std::vector<Method> selected(t.methods.begin(),
                                       t.methods.begin() + std::ptrdiff_t(methods.size()));
    const std::vector<TimeSpread> spreads = time_spreads(t.ns, selected);
    if (o.json)
      j["cpu_time"] = cpu_times_json(spreads, records, o.rounds);
    else
      out << "\n", print_cpu_times(out, spreads, records, o.rounds);
  }
  if (!o.time_ratio.empty()) {
    if (!o.json && o.time) out << "\n";
    j["time_ratio"] = print_time_ratios(o, records, t, out);
  }
}

int run_classify(const ClassifyOptions& o, const Io& io) {
  if (!o.per_query.empty()) check_output_path(o.per_query);
  const std::vector<Method> methods = methods_named(o.methods, o.gate);
  const ClassifiedFiles in = classify_files(o.files, methods, o.kind);
  const Classification& c = in.total;

  const ReportContext ctx{o.gate};
  ToiClassifiedFiles toi;
  if (o.toi) toi = classify_toi_files(in, methods, o.width);
  if (!o.per_query.empty())
    write_file_atomically(o.per_query, per_query_csv(in.all, c, o.toi ? &toi.total : nullptr));
  nlohmann::ordered_json j;
  if (o.json)
    j = classification_json(in.files, c, ctx);
  else
    print_table(io.out, in.files, c, ctx);
  if (o.toi && o.json) j["toi"] = toi_json(toi.files, toi.total);
  if (o.toi && !o.json) io.out << "\n", print_toi_table(io.out, toi.files, toi.total);
  report_query_times(o, in.all, methods, j, io.out);
  if (o.json) print_json(io.out, j);
  std::size_t disagreements = report_disagreements(in.all, methods, c, io.err);
  if (o.toi) disagreements += report_broken_times(in.all, methods, toi.total, io.err);
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
  cmd->add_option("--time-ratio", o->time_ratio,
                  "also time each query alone (thread CPU time, the least\n"
                  "disturbed of --rounds batches) and print each method's\n"
                  "time over BASE's: the maximum over the queries (and\n"
                  "where), the median and how many exceed --ratio-limit")
      ->type_name("BASE")
      ->check(known_method());
  add_number_option(*cmd, "--ratio-limit", o->ratio_limit,
                    "the ratio --time-ratio counts the queries above (default 1.1)", "R", 1e-3,
                    1e3);
  cmd->add_flag("--time", o->time,
                "also time each query alone (thread CPU time, the least\n"
                "disturbed of --rounds batches) and print each method's\n"
                "median, 90th percentile and maximum per query (and the\n"
                "slowest query), beside the table's wall-clock means");
  add_number_option(*cmd, "--rounds", o->rounds,
                    "--time's and --time-ratio's timed batches per query and\n"
                    "method (default 7)",
                    "N", 1, 100);
  cmd->add_flag("--toi", o->toi,
                "also the time of impact of every method that gives one:\n"
                "late, zero and how early against the exact earliest\n"
                "contact (a second table, or \"toi\" in --json); with\n"
                "--per-query, each method's enclosure t_lo, t_hi too");
  cmd->add_option("--width", o->width,
                  "the width of enclosure asked of each time of impact\n"
                  "(default 2^-30 of the step)")
      ->type_name("W")
      ->check(CLI::Range(0x1p-52, 1.0));
  cmd->add_flag("--check", o->check,
                "exit 1 if exact disagrees with a file's truth, or a method\n"
                "breaks its promise (robust's exact answers, a conservative\n"
                "plug-in's misses) on any query (with --toi: or a time breaks\n"
                "its promise); without --check classify exits 0");
  return {cmd, [o](const Io& io) { return run_classify(*o, io); }};
}

}  // namespace fdh::verify
