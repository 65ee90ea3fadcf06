// Runs methods side by side on the same queries and tallies them against a truth.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

struct Tally {
  long tp = 0, tn = 0, fp = 0, fn = 0;
  long na = 0;              // queries the method does not apply to (counted in nothing else)
  double ns_per_query = 0;  // mean over the queries it applies to
  long errors() const { return fp + fn; }
  long decided() const { return tp + tn + fp + fn; }
};

inline constexpr char kNotApplicable = -1;

struct MethodResult {
  std::string name;
  Tally tally;
  std::vector<char> verdict;  // per query: 1 = hit, 0 = no hit, kNotApplicable
  Promise promise = Promise::None;
  DisagreementTally against_exact;  // against the twin (not the file's truth), judged by promise
};

// What the tallies count against: the file's truth (every query has one), exact (none has), or
// the file's truth where given, else exact.
enum class TruthSource { File, Exact, Mixed };

// "file", "exact" or "mixed", as in classify's JSON.
const char* truth_source_name(TruthSource s);

struct Classification {
  std::size_t queries = 0;
  TruthSource truth = TruthSource::Exact;
  std::vector<char> reference;  // per query: the file's truth where given, else exact's verdict
  std::vector<char> exact;      // per query: the exact twin's verdict (registry.hpp)
  std::vector<MethodResult> methods;
  std::size_t static_vf = 0, moving_vf = 0, edge_edge = 0;  // the queries by kind
};

// The seconds one call of `pass` takes: one call, then, if it took less than about 20 ms, the
// mean of enough further calls (at most 1000) to fill that.
double seconds_per_pass(const std::function<void()>& pass);

// Any queries, with the file's truth per query (truth[i] for queries[i], nullopt where the file
// gives none; an empty vector: none at all); a method that does not apply to a query
// (Method::applies_to) gets kNotApplicable there. Each method's time is the mean over enough
// passes to fill about 20 ms, so that short files still give a stable ns per query.
// `progress` hears each method's first pass every 16 queries ("classify METHOD", queries): a
// slow plug-in's run shows it is alive, a fast method's timing does not feel it.
Classification classify(const std::vector<Query>& queries,
                        const std::vector<std::optional<bool>>& truth,
                        const std::vector<Method>& methods, const ProgressSink& progress = {});

// Calls progress every 16th query of a method's first pass (classify, classify_toi).
struct PassProgress {
  const ProgressSink& sink;
  std::string stage;
  long total = 0;
  bool first = true;  // the first pass only: the later ones re-time it
  void at(std::size_t i) const {
    if (first && sink && i % 16 == 0) sink({stage, long(i), total, "queries"});
  }
};

// The classifications of consecutive groups (files) joined into one: counts add up, times are
// weighted by the queries each method applied to.
Classification join(const std::vector<Classification>& parts);

}  // namespace fdh::verify
