// CCD on the benchmark sample (FDH_CCD_SAMPLE, skipped without one): for each set (a
// folder: erleben-sliding-spike, unit-tests, ...) and each method that decides moving queries,
// the mean, median and maximum time per query. Each query is timed on its own, as the mean of
// `reps` back-to-back calls (reps chosen so that one timing lasts about 2 µs or more: the
// clock's own cost stays small beside it).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/io/query_io.hpp"
#include "sample_sets.hpp"
#include "suites.hpp"

namespace fdh::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_per_call(const verify::Method& m, const Query& q) {
  int reps = 1;
  for (;;) {
    const auto start = Clock::now();
    long hits = 0;
    for (int r = 0; r < reps; ++r) hits += m.hit(q);
    benchmark::DoNotOptimize(hits);
    const double s = std::chrono::duration<double>(Clock::now() - start).count();
    if (s >= 2e-6 || reps >= 1024) return s / reps;
    reps *= 4;
  }
}

void time_set(benchmark::State& state, const verify::Method& m, const std::vector<Query>& qs) {
  std::vector<double> t(qs.size());
  for (auto _ : state)
    for (std::size_t i = 0; i < qs.size(); ++i) t[i] = seconds_per_call(m, qs[i]);
  std::vector<double> sorted = t;
  std::sort(sorted.begin(), sorted.end());
  const double n = double(t.size());
  state.counters["queries"] = n;
  state.counters["mean_ns"] = 1e9 * std::accumulate(t.begin(), t.end(), 0.0) / n;
  state.counters["median_ns"] = 1e9 * sorted[sorted.size() / 2];
  state.counters["max_ns"] = 1e9 * sorted.back();
}

}  // namespace

void register_ccd_sample() {
  for (auto& [name, queries] : sample_sets()) {
    if (queries.empty()) continue;
    for (const verify::Method& m : verify::all_methods()) {
      auto qs = std::make_shared<std::vector<Query>>();
      for (const Query& q : queries)
        if (m.applies_to(q)) qs->push_back(q);
      if (qs->size() != queries.size()) continue;  // a method for some of the set only
      benchmark::RegisterBenchmark(("ccd_sample/" + m.name + "/" + name).c_str(),
                                   [m, qs](benchmark::State& state) { time_set(state, m, *qs); })
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace fdh::bench
