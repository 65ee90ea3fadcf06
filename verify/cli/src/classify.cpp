// fdhcert classify: every method side by side on query files.
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "commands.hpp"
#include "fdh/classify/classify.hpp"
#include "fdh/os/atomic_file.hpp"
#include "min_distance_option.hpp"

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
(with --min-distance D > 0 also "min_distance": D after "gate")
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
for the clock); with --toi also "NAME/toi", each method's time of impact timed
the same way. With --time-ratio BASE it
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

// The job's options (fdh/classify/classify.hpp) and what only the command line has: how to print
// and when to exit 1.
struct ClassifyCli {
  ClassifyOptions job;
  bool json = false, check = false;
  std::string per_query;
  ProgressWhen progress = ProgressWhen::Auto;
};

int run_classify(const ClassifyCli& o, const Io& io) {
  if (!o.per_query.empty()) check_output_path(o.per_query);
  ClassifyOptions job = o.job;
  if (!job.kind.empty()) job.kind = job.kind == "ee" ? "edge-edge" : "vertex-face";  // --kind
  ClassifyResult r;
  ProgressLine progress(io.err, progress_wanted(io, o.progress));
  job.progress = progress.sink();  // off a terminal: lines once the run has taken 10 s
  try {
    r = classify_job(job);
  } catch (const std::invalid_argument& e) {  // the options, checked by the job
    throw UsageError(e.what());
  }
  progress.clear();
  if (!o.per_query.empty()) write_file_atomically(o.per_query, r.per_query_csv());
  if (o.json)
    print_json(io.out, r.to_json());
  else
    io.out << r.text();
  // Only when there is something to say: standard error is tied to standard output, so a write
  // to it flushes the output before run_cli checks it (and an error's reason would be lost).
  if (const std::string found = r.findings_text(); !found.empty()) io.err << found;
  return o.check && r.broken() > 0 ? 1 : 0;
}

}  // namespace

Command add_classify(CLI::App& app) {
  auto cli = std::make_shared<ClassifyCli>();
  ClassifyOptions* o = &cli->job;
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
  cmd->add_flag("--json", cli->json, "print one JSON object instead of the table (below)");
  cmd->add_option("--per-query", cli->per_query,
                  "also write FILE, one CSV row per query: id, truth, each\n"
                  "method's verdict (0/1/n/a), then exact's contact kind\n"
                  "(\"moving\" for a moving query) and earliest contact time\n"
                  "(a rational, or lo..hi)")
      ->type_name("FILE");
  add_plugin_option(*cmd);
  add_quiet_flag(*cmd, cli->progress);
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
                "slowest query), beside the table's wall-clock means; with\n"
                "--toi, each time of impact too (rows NAME/toi)");
  add_number_option(*cmd, "--rounds", o->rounds,
                    "--time's and --time-ratio's timed batches per query and\n"
                    "method (default 7)",
                    "N", 1, 100);
  CLI::Option* toi = cmd->add_flag("--toi", o->toi,
                                   "also the time of impact of every method that gives one:\n"
                                   "late, zero and how early against the exact earliest\n"
                                   "contact (a second table, or \"toi\" in --json); with\n"
                                   "--per-query, each method's enclosure t_lo, t_hi too");
  cmd->add_option("--width", o->width,
                  "with --toi: the width of enclosure asked of each time of\n"
                  "impact, in [2^-52, 1] steps (default 2^-30; 2^-N is taken)")
      ->type_name("W")
      ->transform(real_range(0x1p-52, 1.0, "[2^-52, 1]"))
      ->needs(toi);
  add_min_distance_option(*cmd, o->min_distance,
                          "ask every query at minimum separation D: a hit is any time\n"
                          "within distance D, not only contact (docs/methods.md);\n"
                          "a file's truth counts only where the file's D is this D;\n"
                          "methods that answer contact only show n/a (default 0)");
  cmd->add_flag("--check", cli->check,
                "exit 1 if exact disagrees with a file's truth, or a method\n"
                "breaks its promise (robust's exact answers, a conservative\n"
                "plug-in's misses) on any query (with --toi: or a time breaks\n"
                "its promise); without --check classify exits 0");
  return {cmd, [cli](const Io& io) { return run_classify(*cli, io); }};
}

}  // namespace fdh::verify
