#include "fdh/classify/replay.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "fdh/check/classify.hpp"
#include "fdh/check/classify_toi.hpp"
#include "fdh/classify/classify_files.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/record_scope.hpp"
#include "fdh/os/atomic_file.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;

// The stored cases under the paths, of every kind: static and moving vertex-face, edge-edge;
// each asked at δ (a stored truth kept only where the case's own δ is δ).
std::vector<QueryRecord> read_cases(const std::vector<std::string>& paths, double min_distance) {
  std::vector<QueryRecord> cases;
  for (const std::string& p : paths)
    for (const std::string& f : list_query_files(p))
      for (QueryRecord& q : read_native(f)) {
        if (!q.has_truth()) throw InputError(q.file, q.line, "a stored case needs a truth");
        cases.push_back(std::move(q));
      }
  if (cases.empty()) throw InputError(paths.front(), 0, "no stored case");
  ask_at(cases, min_distance);
  return cases;
}

// Method k's cases against the stored truths, from the findings: a disagreement with the twin
// where the twin keeps the truth, or the twin's own lost truth where the method agrees with it.
Failing failing_of(const std::vector<QueryRecord>& cases, const MethodResult& m,
                   const std::vector<Finding>& found) {
  Failing f{m.name, m.promise, {}, {}, {}, {}, {}};
  std::vector<const Finding*> at(cases.size(), nullptr);
  std::vector<char> lost(cases.size(), 0);  // the twin differs from the stored truth
  for (const Finding& x : found)
    if (x.truth)
      lost[x.query] = 1;
    else if (x.method == m.name)
      at[x.query] = &x;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (m.verdict[i] == kNotApplicable) continue;
    const std::string w = place_of(cases[i], Place::Line);
    if (const Finding* x = at[i]) {
      f.tally.add(m.promise, x->said, !x->said);
      (x->said ? f.false_alarms : f.misses).push_back(w);
      if (!lost[i]) f.cases.push_back(w), f.words.push_back(x->words);
    } else if (lost[i]) {
      f.cases.push_back(w), f.words.push_back(w + ": as exact, against the stored truth");
    }
  }
  return f;
}

// Each method's listed times, from the time findings.
std::vector<ReplayTimes> times_of(const std::vector<QueryRecord>& cases,
                                  const ToiClassification& toi,
                                  const std::vector<TimeFinding>& found) {
  std::vector<ReplayTimes> out;
  for (const ToiResult& m : toi.methods) {
    ReplayTimes t{m.name, m.promise, {}, {}, {}, {}, {}, {}};
    for (const TimeFinding& f : found) {
      if (f.method != m.name) continue;
      const std::string w = place_of(cases[f.query], Place::Line);
      if (f.check.late) t.late.push_back(w);
      if (f.check.zero) t.zero.push_back(w);
      if (f.early) t.early.push_back(w);
      if (!f.check.kept) t.broken.push_back(w);
      if (f.judgement == Judgement::Allowed) t.allowed.push_back(w);
      t.words.push_back(w + ": " + f.words);
    }
    out.push_back(std::move(t));
  }
  return out;
}

// {"misses": M, "false_alarms": F} of the disagreements that `j` judges.
Json by_direction(const Failing& f, Judgement j) {
  const bool miss = judge(f.promise, false, true) == j, alarm = judge(f.promise, true, false) == j;
  return {{"misses", miss ? f.misses.size() : 0},
          {"false_alarms", alarm ? f.false_alarms.size() : 0}};
}

// "1 miss (breaks CONSERVATIVE); 3 false alarms (allowed: conservative)": a method's
// disagreements with the twin, by what its promise makes of them and by direction.
std::string kinds_of(const Failing& f) {
  std::string out;
  for (const Judgement j : {Judgement::Broken, Judgement::Allowed, Judgement::Unpromised}) {
    const Json n = by_direction(f, j);
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

}  // namespace

void ReplayOptions::validate() const {
  const auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (paths.empty()) bad("replay needs at least one path");
  if (!methods.empty()) select_methods(methods);
  if (!(width >= 0x1p-52 && width <= 1)) bad("width must be in [2^-52, 1]");
  if (!(tolerance >= 0 && tolerance <= 1)) bad("toi tolerance must be in [0, 1]");
  if (!std::isfinite(min_distance) || min_distance < 0)
    bad(fmt::format("min distance must be finite and >= 0, not {}", min_distance));
}

ReplayResult replay_job(const ReplayOptions& o) {
  o.validate();
  const std::vector<Method> methods = o.methods.empty() ? all_methods() : select_methods(o.methods);
  const std::vector<QueryRecord> cases = read_cases(o.paths, o.min_distance);
  const std::vector<Query> queries = queries_of(cases);
  const RecordScope asking(cases, queries);  // a plug-in's crash names FILE:LINE
  const Classification c = classify(queries, truths_of(cases), methods);
  const std::vector<Finding> found = findings(c, cases, methods, Place::Line);
  ReplayResult r;
  r.options = o;
  r.cases = cases.size();
  for (const Finding& f : found)
    if (f.truth) r.twin_mismatches.push_back(place_of(cases[f.query], Place::Line));
  for (const MethodResult& m : c.methods) r.failing.push_back(failing_of(cases, m, found));
  if (o.toi) {
    const ToiClassification toi = classify_toi(queries, methods, o.width);
    r.times = times_of(cases, toi, time_findings(toi, methods, o.tolerance));
  }
  return r;
}

Json ReplayResult::to_json() const {
  Json methods = Json::object();
  for (const Failing& f : failing)
    methods[f.name] = {{"failing", f.cases.size()},
                       {"cases", f.cases},
                       {"promise", to_string(f.promise)},
                       {"misses", f.misses},
                       {"false_alarms", f.false_alarms},
                       {"broken", by_direction(f, Judgement::Broken)},
                       {"allowed", by_direction(f, Judgement::Allowed)},
                       {"no_promise", by_direction(f, Judgement::Unpromised)}};
  Json j = {{"cases", cases}, {"exact_mismatches", twin_mismatches}, {"methods", methods}};
  if (options.min_distance > 0) j["min_distance"] = options.min_distance;  // 0: as before δ
  for (const ReplayTimes& t : times)
    j["toi"][t.method] = {{"late", t.late},
                          {"zero", t.zero},
                          {"early", t.early},
                          {"broken", t.broken},
                          {"promise", to_string(t.promise)},
                          {"allowed", t.allowed}};
  return j;
}

std::string ReplayResult::text() const {
  std::ostringstream out;
  out << "replayed " << cases << " cases"
      << (options.min_distance > 0 ? fmt::format(" at minimum separation {}", options.min_distance)
                                   : "")
      << "; exact "
      << (twin_mismatches.empty()
              ? "gives every stored truth"
              : "DISAGREES with " + std::to_string(twin_mismatches.size()) + " stored truths")
      << "\n";
  for (const Failing& f : failing) {
    const std::string kinds = kinds_of(f);
    out << "  " << f.name << ": " << f.cases.size() << " failing"
        << (kinds.empty() ? "" : "; " + kinds) << "\n";
    for (const std::string& w : f.words) out << "    " << w << "\n";
  }
  for (const ReplayTimes& t : times) {
    out << "  " << t.method << " time of impact: " << t.late.size() << " late, " << t.zero.size()
        << " zero, " << t.early.size() << " early, " << t.broken.size() << " breaking its promise, "
        << t.allowed.size() << " allowed by it (" << to_string(t.promise) << ")\n";
    for (const std::string& w : t.words) out << "    " << w << "\n";
  }
  return out.str();
}

void ReplayResult::write(const std::string& dir) const {
  std::filesystem::create_directories(dir);
  write_file_atomically(dir + "/replay.json", json_text(to_json(), "replay.json"));
  write_file_atomically(dir + "/replay.txt", text());
}

}  // namespace fdh::verify
