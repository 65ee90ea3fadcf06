// Minimum separation (issue 30) on the benchmark sample (FDH_CCD_SAMPLE, skipped without one)
// at δ = D = 1e-6: per query, `robust` at δ = 0, robust within δ (verdict), robust's TOI within δ
// (w = 2^-30) and the float baseline within δ (float_cubic at δ > 0), each query timed on its
// own (per_call.hpp), the four in turn. Counters: mean and median ns per query of each; the
// queries robust's filter leaves to the exact test at δ; the float baseline's false positives and
// negatives against robust's verdict (the exact one: robust's fallback is exact::ccd_hit).
// After the run, print_delta_ratios() prints the targets: robust δ / robust 0 and
// robust TOI δ / robust δ, medians over the queries.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "fdh/ccd/float_cubic.hpp"
#include "fdh/ccd/robust.hpp"
#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"
#include "per_call.hpp"
#include "sample_sets.hpp"
#include "suites.hpp"

namespace fdh::bench {
namespace {

constexpr double kDelta = 1e-6;

struct Timed {
  const char* name;
  bool at_zero;  // on the query at δ = 0, else at δ = kDelta
  std::function<double(const Query&)> run;
};
std::vector<Timed> timed_methods() {
  const auto robust = [](const Query& q) { return double(robust_ccd(q, &exact::ccd_hit)); };
  return {{"robust0", true, robust},
          {"robust_delta", false, robust},
          {"robust_toi_delta", false,
           [](const Query& q) { return robust_ccd_toi(q, 0x1p-30, &exact::ccd_toi).t_lo; }},
          {"float_delta", false, [](const Query& q) { return double(float_cubic(q)); }}};
}

// The medians of each run (by benchmark name, then method), for print_delta_ratios().
std::map<std::string, std::map<std::string, double>>& medians() {
  static std::map<std::string, std::map<std::string, double>> m;
  return m;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void count_answers(benchmark::State& state, const std::vector<Query>& qs) {
  double uncertain = 0, fp = 0, fn = 0, hits = 0;
  for (const Query& q : qs) {
    const bool truth = robust_ccd(q, &exact::ccd_hit), naive = float_cubic(q);
    uncertain += robust_ccd_filter(q) == Filtered::Uncertain;
    hits += truth, fp += naive && !truth, fn += !naive && truth;
  }
  state.counters["hits"] = hits;
  state.counters["robust_uncertain"] = uncertain;
  state.counters["float_fp"] = fp;
  state.counters["float_fn"] = fn;
}

// qs at δ = 0 and the same at δ = kDelta.
void time_delta(benchmark::State& state, const std::string& name, const std::vector<Query>& qs,
                const std::vector<Query>& at_delta) {
  const std::vector<Timed> methods = timed_methods();
  std::vector<std::vector<double>> t(methods.size(), std::vector<double>(qs.size()));
  for (auto _ : state)
    for (std::size_t i = 0; i < qs.size(); ++i)
      for (std::size_t j = 0; j < methods.size(); ++j) {
        const std::size_t m = (i + j) % methods.size();  // each query starts with the next
        t[m][i] = seconds_per_call(methods[m].run, methods[m].at_zero ? qs[i] : at_delta[i]);
      }
  state.counters["queries"] = double(qs.size());
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const double med = 1e9 * median(t[m]);
    medians()[name][methods[m].name] = med;
    state.counters[std::string(methods[m].name) + "_median_ns"] = med;
    state.counters[std::string(methods[m].name) + "_mean_ns"] =
        1e9 * std::accumulate(t[m].begin(), t[m].end(), 0.0) / double(qs.size());
  }
  count_answers(state, at_delta);
}

void add(const std::string& name, std::vector<Query> qs) {
  if (qs.empty()) return;
  auto at_delta = std::make_shared<std::vector<Query>>(qs);
  for (Query& q : *at_delta) q.min_distance = kDelta;
  auto zero = std::make_shared<std::vector<Query>>(std::move(qs));
  const std::string full = "delta/sample/" + name;
  benchmark::RegisterBenchmark(full.c_str(),
                               [zero, at_delta, full](benchmark::State& state) {
                                 time_delta(state, full, *zero, *at_delta);
                               })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

void register_ccd_delta() {
  std::vector<Query> all;
  for (auto& [name, set] : sample_sets()) {
    all.insert(all.end(), set.begin(), set.end());
    add(name, std::move(set));
  }
  add("all", std::move(all));
}

void print_delta_ratios(std::ostream& out) {
  if (medians().empty()) return;
  out << fmt::format(
      "\nminimum separation at D = {:g}, medians per query (targets: robust δ / "
      "robust 0 <= 2, robust TOI δ / robust δ <= 1.3)\n",
      kDelta);
  out << fmt::format("{:<50}{:>12}{:>12}{:>14}{:>14}\n", "", "robust 0", "robust δ", "δ / 0",
                     "TOI δ / δ");
  for (const auto& [name, m] : medians())
    out << fmt::format("{:<50}{:>9.1f} ns{:>9.1f} ns{:>14.2f}{:>14.2f}\n", name, m.at("robust0"),
                       m.at("robust_delta"), m.at("robust_delta") / m.at("robust0"),
                       m.at("robust_toi_delta") / m.at("robust_delta"));
}

}  // namespace fdh::bench
