// Runs the methods' times of impact side by side on the same queries (the TOI decisions,
// registry.hpp), each timed, and tallies each against the exact earliest contact through the
// checker (checker.hpp check_time_given): late, early, zero, enclosure and verdict errors.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

struct ToiResult {
  std::string name;
  TimePromise promise = TimePromise::None;
  long na = 0;              // queries it gives no time for
  double ns_per_query = 0;  // mean over the queries it gives a time for
  TimeTally tally;
  std::vector<Toi> said;          // per query; {false, 1, 1} where n/a
  std::vector<char> applies;      // per query: 1 where it gave a time
  std::vector<TimeCheck> checks;  // per query: the checker's findings where it gave a time
};

struct ToiClassification {
  double width = kDefaultToiWidth;  // the enclosure width asked of every method
  std::size_t queries = 0;
  std::vector<TimeTwin> twin;  // per query: the exact verdict and t*
  std::vector<ToiResult> methods;
};

// The methods of `methods` that give a time at all, each timed over enough passes to fill about
// 20 ms (as classify does), then checked query by query.
ToiClassification classify_toi(const std::vector<Query>& queries,
                               const std::vector<Method>& methods, double width,
                               const ProgressSink& progress = {});

// Consecutive groups (files) joined into one: counts add up, early times are pooled, times
// are weighted by the queries each method gave a time for.
ToiClassification join(const std::vector<ToiClassification>& parts);

}  // namespace fdh::verify
