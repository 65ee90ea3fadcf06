// fdhcert replay: re-run stored cases; exact must still give each stored truth.
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fdh/check/checker.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/check/classify_toi.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/record_scope.hpp"
#include "plugin_option.hpp"

namespace fdh::verify {
namespace {

const char* const kReplayAbout =
    R"(re-run stored cases: which methods still fail where

Re-runs stored cases of every kind: static and moving vertex-face, edge-edge
(native query files; a folder means every *.vf below it, such as corpus/ or a
fuzz --out folder). Every case must carry a truth.

  exact must still give each case's stored truth: if it does not, replay names
  the case and exits with status 1.
  For every other method it reports which cases it still gets wrong (a case
  it makes no decision on is not counted).
  With --toi, also the cases where a method's time of impact is late (a
  contact missed, or t_lo after the exact earliest contact) or 0 where the
  contact is later, and those earlier than the exact contact by more than
  --toi-tolerance of the step (fuzz --toi's early findings).)";

const char* const kReplayFooter =
    R"(--json prints {"cases": N, "exact_mismatches": [...],
               "methods": {"<name>": {"failing": K, "cases": [...]}}}
and with --toi also "toi": {"<name>": {"late": [...], "zero": [...],
                                       "early": [...], "broken": [...]}}
(broken: the cases where the time breaks the method's time promise).)";

struct ReplayOptions {
  std::vector<std::string> paths, methods;
  bool json = false, toi = false;
  double width = kDefaultToiWidth;
  double tolerance = kDefaultToiTolerance;  // how early a time may be before it is listed
};

// The stored cases under the paths, of every kind: static and moving vertex-face, edge-edge.
std::vector<QueryRecord> read_cases(const std::vector<std::string>& paths) {
  std::vector<QueryRecord> cases;
  for (const std::string& p : paths)
    for (const std::string& f : list_query_files(p))
      for (QueryRecord& q : read_native(f)) {
        if (!q.has_truth()) throw InputError(q.file, q.line, "a stored case needs a truth");
        cases.push_back(std::move(q));
      }
  if (cases.empty()) throw InputError(paths.front(), 0, "no stored case");
  return cases;
}

// What replay found: the cases where the twin lost its stored truth, and per method (in the
// order run) the cases it answers differently from the reference.
struct Replay {
  std::vector<std::string> twin_mismatches;
  std::vector<std::pair<std::string, std::vector<std::string>>> failing;
  struct Times {
    std::string method;
    std::vector<std::string> late, zero, early, broken;
  };
  std::vector<Times> times;  // with --toi: per method that gives a time
};

// The cases where each method's time is late, 0 too early, or breaks its promise (checker.hpp).
void replay_times(const std::vector<QueryRecord>& cases, const std::vector<Query>& queries,
                  const std::vector<Method>& methods, const ReplayOptions& o, Replay& r) {
  const double width = o.width;
  const ToiClassification toi = classify_toi(queries, methods, width);
  for (const ToiResult& m : toi.methods) {
    Replay::Times t{m.name, {}, {}, {}, {}};
    const Method& method = *std::find_if(methods.begin(), methods.end(),
                                         [&](const Method& x) { return x.name == m.name; });
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (!m.applies[i]) continue;
      const TimeCheck c = check_time_given(method, queries[i], width, m.said[i], toi.twin[i]);
      if (c.late) t.late.push_back(where(cases[i]));
      if (c.zero) t.zero.push_back(where(cases[i]));
      if (c.early > o.tolerance) t.early.push_back(where(cases[i]));
      if (!c.kept) t.broken.push_back(where(cases[i]));
    }
    r.times.push_back(std::move(t));
  }
}

Replay replay(const std::vector<QueryRecord>& cases, const Classification& c) {
  Replay r;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (twin_matches_truth(stated(cases[i].truth), c.exact[i]) == std::optional<bool>(false))
      r.twin_mismatches.push_back(where(cases[i]));
  for (const MethodResult& m : c.methods) {
    std::vector<std::string> list;
    for (std::size_t i = 0; i < cases.size(); ++i)
      if (m.verdict[i] != kNotApplicable && m.verdict[i] != c.reference[i])
        list.push_back(where(cases[i]));
    r.failing.emplace_back(m.name, std::move(list));
  }
  return r;
}

void print_replay(const Replay& r, std::size_t cases, bool json, std::ostream& out) {
  if (json) {
    nlohmann::ordered_json methods = nlohmann::ordered_json::object();
    for (const auto& [name, list] : r.failing)
      methods[name] = {{"failing", list.size()}, {"cases", list}};
    nlohmann::ordered_json j = {
        {"cases", cases}, {"exact_mismatches", r.twin_mismatches}, {"methods", methods}};
    for (const Replay::Times& t : r.times)
      j["toi"][t.method] = {
          {"late", t.late}, {"zero", t.zero}, {"early", t.early}, {"broken", t.broken}};
    print_json(out, j);
    return;
  }
  out << "replayed " << cases << " cases; exact "
      << (r.twin_mismatches.empty()
              ? "gives every stored truth"
              : "DISAGREES with " + std::to_string(r.twin_mismatches.size()) + " stored truths")
      << "\n";
  for (const auto& [name, list] : r.failing) {
    out << "  " << name << ": " << list.size() << " failing\n";
    for (const std::string& w : list) out << "    " << w << "\n";
  }
  for (const Replay::Times& t : r.times) {
    out << "  " << t.method << " time of impact: " << t.late.size() << " late, " << t.zero.size()
        << " zero, " << t.early.size() << " early, " << t.broken.size()
        << " breaking its promise\n";
    for (const std::string& w : t.late) out << "    late: " << w << "\n";
    for (const std::string& w : t.early) out << "    early: " << w << "\n";
  }
}

int run_replay(const ReplayOptions& o, const Io& io) {
  const std::vector<Method> methods = methods_named(o.methods);
  const std::vector<QueryRecord> cases = read_cases(o.paths);
  const std::vector<Query> queries = queries_of(cases);
  const RecordScope asking(cases, queries);  // a plug-in's crash names FILE:LINE
  Replay r = replay(cases, classify(queries, truths_of(cases), methods));
  if (o.toi) replay_times(cases, queries, methods, o, r);
  print_replay(r, cases.size(), o.json, io.out);
  for (const std::string& w : r.twin_mismatches)
    io.err << "fdhcert: exact no longer gives the stored truth at " << w << "\n";
  return r.twin_mismatches.empty() ? 0 : 1;
}

}  // namespace

Command add_replay(CLI::App& app) {
  auto o = std::make_shared<ReplayOptions>();
  CLI::App* cmd = add_command(app, "replay", kReplayAbout, kReplayFooter);
  cmd->add_option("PATH", o->paths, "a case file, or a folder of them")->required();
  add_methods_option(*cmd, o->methods, "comma-separated methods (default: all)");
  add_plugin_option(*cmd);
  cmd->add_flag("--json", o->json, "print one JSON object (below)");
  cmd->add_flag("--toi", o->toi,
                "also re-check every method's time of impact: the cases\n"
                "where it is late, 0, or breaks its time promise");
  cmd->add_option("--width", o->width, "the enclosure width asked of each time (default 2^-30)")
      ->type_name("W")
      ->check(CLI::Range(0x1p-52, 1.0));
  cmd->add_option("--toi-tolerance", o->tolerance,
                  "with --toi: list a time as early when t* - t_lo exceeds\n"
                  "T steps (default 0.1, as fuzz --toi)")
      ->type_name("T")
      ->check(CLI::Range(0.0, 1.0))
      ->needs("--toi");
  return {cmd, [o](const Io& io) { return run_replay(*o, io); }};
}

}  // namespace fdh::verify
