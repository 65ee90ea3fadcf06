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

// One method's cases against the stored truths, and each disagreement with the twin in the
// checker's words (checker.hpp: verdict_words), counted by direction and by what the method's
// promise makes of it.
struct Failing {
  std::string name;
  Promise promise = Promise::None;
  std::vector<std::string> cases;                 // where it differs from the stored truth
  std::vector<std::string> words;                 // per case: the checker's words, or why none
  std::vector<std::string> misses, false_alarms;  // against the twin
  DisagreementTally tally;
};

// What replay found: the cases where the twin lost its stored truth, and per method (in the
// order run) the cases it answers differently from the reference.
struct Replay {
  std::vector<std::string> twin_mismatches;
  std::vector<Failing> failing;
  struct Times {
    std::string method;
    TimePromise promise = TimePromise::None;
    std::vector<std::string> late, zero, early, broken, allowed;
    std::vector<std::string> words;  // per listed case: WHERE: the checker's judged words
  };
  std::vector<Times> times;  // with --toi: per method that gives a time
};

// The cases where each method's time is late, 0 too early, or breaks its promise (checker.hpp),
// and of those listed, the ones its time promise allows.
void replay_times(const std::vector<QueryRecord>& cases, const std::vector<Query>& queries,
                  const std::vector<Method>& methods, const ReplayOptions& o, Replay& r) {
  const double width = o.width;
  const ToiClassification toi = classify_toi(queries, methods, width);
  for (const ToiResult& m : toi.methods) {
    const Method& method = *std::find_if(methods.begin(), methods.end(),
                                         [&](const Method& x) { return x.name == m.name; });
    Replay::Times t{m.name, method.time_promise, {}, {}, {}, {}, {}, {}};
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (!m.applies[i]) continue;
      const TimeCheck c = check_time_given(method, queries[i], width, m.said[i], toi.twin[i]);
      const std::string w = where(cases[i]);
      if (c.late) t.late.push_back(w);
      if (c.zero) t.zero.push_back(w);
      if (c.early > o.tolerance) t.early.push_back(w);
      if (!c.kept) t.broken.push_back(w);
      if (!c.late && !c.zero && !(c.early > o.tolerance) && c.kept) continue;
      if (judge(method, c) == Judgement::Allowed) t.allowed.push_back(w);
      t.words.push_back(w + ": " + judged_time_words(method, c));
    }
    r.times.push_back(std::move(t));
  }
}

Failing failing_of(const std::vector<QueryRecord>& cases, const Classification& c,
                   const MethodResult& m, const Method& method) {
  Failing f{m.name, m.promise, {}, {}, {}, {}, {}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (m.verdict[i] == kNotApplicable) continue;
    const bool said = m.verdict[i], twin = c.exact[i];
    if (said != twin) {
      f.tally.add(m.promise, said, twin);
      (said ? f.false_alarms : f.misses).push_back(where(cases[i]));
    }
    if (m.verdict[i] == c.reference[i]) continue;
    f.cases.push_back(where(cases[i]));
    f.words.push_back(said == twin ? where(cases[i]) + ": as exact, against the stored truth"
                                   : verdict_words(method, said, twin, where(cases[i])));
  }
  return f;
}

Replay replay(const std::vector<QueryRecord>& cases, const Classification& c,
              const std::vector<Method>& methods) {
  Replay r;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (twin_matches_truth(stated(cases[i].truth), c.exact[i]) == std::optional<bool>(false))
      r.twin_mismatches.push_back(where(cases[i]));
  for (std::size_t k = 0; k < c.methods.size(); ++k)
    r.failing.push_back(failing_of(cases, c, c.methods[k], methods[k]));
  return r;
}

// {"misses": M, "false_alarms": F} of the disagreements that `j` judges.
nlohmann::ordered_json by_direction(const Failing& f, Judgement j) {
  const bool miss = judge(f.promise, false, true) == j, alarm = judge(f.promise, true, false) == j;
  return {{"misses", miss ? f.misses.size() : 0},
          {"false_alarms", alarm ? f.false_alarms.size() : 0}};
}

void print_replay_json(const Replay& r, std::size_t cases, std::ostream& out) {
  nlohmann::ordered_json methods = nlohmann::ordered_json::object();
  for (const Failing& f : r.failing)
    methods[f.name] = {{"failing", f.cases.size()},
                       {"cases", f.cases},
                       {"promise", to_string(f.promise)},
                       {"misses", f.misses},
                       {"false_alarms", f.false_alarms},
                       {"broken", by_direction(f, Judgement::Broken)},
                       {"allowed", by_direction(f, Judgement::Allowed)},
                       {"no_promise", by_direction(f, Judgement::Unpromised)}};
  nlohmann::ordered_json j = {
      {"cases", cases}, {"exact_mismatches", r.twin_mismatches}, {"methods", methods}};
  for (const Replay::Times& t : r.times)
    j["toi"][t.method] = {{"late", t.late},
                          {"zero", t.zero},
                          {"early", t.early},
                          {"broken", t.broken},
                          {"promise", to_string(t.promise)},
                          {"allowed", t.allowed}};
  print_json(out, j);
}

// "1 miss (breaks CONSERVATIVE); 3 false alarms (allowed: conservative)": a method's
// disagreements with the twin, by what its promise makes of them and by direction.
std::string kinds_of(const Failing& f) {
  std::string out;
  for (const Judgement j : {Judgement::Broken, Judgement::Allowed, Judgement::Unpromised}) {
    const nlohmann::ordered_json n = by_direction(f, j);
    const std::size_t misses = n["misses"], alarms = n["false_alarms"];
    if (misses + alarms == 0) continue;
    out += out.empty() ? "" : "; ";
    if (misses) out += std::to_string(misses) + (misses == 1 ? " miss" : " misses");
    if (misses && alarms) out += ", ";
    if (alarms) out += std::to_string(alarms) + (alarms == 1 ? " false alarm" : " false alarms");
    out += " " + judgement_words(j, f.promise);
  }
  return out;
}

void print_replay(const Replay& r, std::size_t cases, bool json, std::ostream& out) {
  if (json) return print_replay_json(r, cases, out);
  out << "replayed " << cases << " cases; exact "
      << (r.twin_mismatches.empty()
              ? "gives every stored truth"
              : "DISAGREES with " + std::to_string(r.twin_mismatches.size()) + " stored truths")
      << "\n";
  for (const Failing& f : r.failing) {
    const std::string kinds = kinds_of(f);
    out << "  " << f.name << ": " << f.cases.size() << " failing"
        << (kinds.empty() ? "" : "; " + kinds) << "\n";
    for (const std::string& w : f.words) out << "    " << w << "\n";
  }
  for (const Replay::Times& t : r.times) {
    out << "  " << t.method << " time of impact: " << t.late.size() << " late, " << t.zero.size()
        << " zero, " << t.early.size() << " early, " << t.broken.size() << " breaking its promise, "
        << t.allowed.size() << " allowed by it (" << to_string(t.promise) << ")\n";
    for (const std::string& w : t.words) out << "    " << w << "\n";
  }
}

int run_replay(const ReplayOptions& o, const Io& io) {
  const std::vector<Method> methods = methods_named(o.methods);
  const std::vector<QueryRecord> cases = read_cases(o.paths);
  const std::vector<Query> queries = queries_of(cases);
  const RecordScope asking(cases, queries);  // a plug-in's crash names FILE:LINE
  Replay r = replay(cases, classify(queries, truths_of(cases), methods), methods);
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
