// The time of each method on each query alone, and how one method's time compares with
// another's query by query (the target "robust is never more than 1.1x exact on any query").
// classify's own times are means over whole files; a per-query bound needs each query timed by
// itself, repeatedly, so that the machine's noise does not decide the maximum.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

// ns per call of each method on each query: result[m][i]. Each query is timed in batches of
// calls long enough (>= about 50 us) for the clock, the methods taking turns, `rounds` times;
// each figure is the minimum over the rounds of the batch's thread CPU time per call (time
// spent waiting for a core is not counted; only disturbances add time, so the minimum is the
// figure least disturbed). A method that does not apply to a query gets 0 there.
std::vector<std::vector<double>> time_each_query(const std::vector<Query>& queries,
                                                 const std::vector<Method>& methods,
                                                 int rounds = 7);

// One method's time per query over the queries it applies to (classify --time): the lower
// median, the 90th percentile (nearest rank: the smallest time at or above 90 % of the queries)
// and the maximum, so median <= p90 <= max; `slowest` is the query of the maximum. queries = 0
// (and times 0) for a method that applies to none.
struct TimeSpread {
  std::string method;
  std::size_t queries = 0;
  double median = 0, p90 = 0, max = 0;  // ns per call, as time_each_query gives them
  std::size_t slowest = 0;
};

// The spread of each method's times (times[m][i] of time_each_query, 0 where it does not apply).
std::vector<TimeSpread> time_spreads(const std::vector<std::vector<double>>& times,
                                     const std::vector<Method>& methods);

// One method's time over a base's, query by query, over the queries of one decision that both
// apply to.
struct TimeRatio {
  std::string method;
  Decision decision = Decision::PointTriangle;
  std::size_t queries = 0;
  double max = 0, median = 0;
  std::size_t worst = 0;  // the query of the maximum
  std::size_t over = 0;   // queries where the ratio exceeds `limit`
};

// The ratio of every method to methods[base], per query decision (point-triangle, vertex-face
// and edge-edge CCD) that has queries; `limit` only counts the queries above it.
std::vector<TimeRatio> time_ratios(const std::vector<Query>& queries,
                                   const std::vector<std::vector<double>>& times,
                                   const std::vector<Method>& methods, std::size_t base,
                                   double limit);

}  // namespace fdh::verify
