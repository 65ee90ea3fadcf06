// Where `robust`'s time goes (issue 33): stages/<set> for each set of the benchmark sample
// (FDH_CCD_SAMPLE, skipped without one), all of it, each of the six hard moving families (the
// 1000 queries of `fdhcert generate <family> --count 1000 --seed 1`), the six together, and the
// six at another seed (2000 each of --seed 3: the held-out set of ../shared/checks/targets.sh).
// For each query: the stage that decides it (fdh::robust_ccd_stage), and the time of robust's
// verdict (the registry's method: its filter, then exact::ccd_hit where the filter is
// uncertain), of its filter alone, of `exact` and of `float-cubic`, each timed on its own
// (per_call.hpp). Counters: the share of queries each stage decides (<stage>_share;
// fallback_share is how often robust runs the exact fallback, reference/'s integers: __int128,
// GMP's mpn beyond), robust's mean ns over the queries each stage decides (<stage>_robust_ns),
// on those left to the fallback the filter's ns (fallback_filter_ns) and the fallback's own
// (fallback_own_ns), the three methods' means and the ratios of means.
#include <benchmark/benchmark.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fdh/ccd/float_cubic.hpp"
#include "fdh/ccd/robust.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/gen/case_seed.hpp"
#include "fdh/gen/families.hpp"
#include "per_call.hpp"
#include "sample_sets.hpp"
#include "suites.hpp"

namespace fdh::bench {
namespace {

constexpr std::array<const char*, 4> kStages = {"volume", "subdivision", "integer", "fallback"};
constexpr std::array<const char*, 6> kHard = {"hourglass",      "two-crossings",
                                              "coplanar",       "sliding-on-edge",
                                              "parallel-edges", "degenerate-edge"};

struct Sums {
  double robust = 0, filter = 0, exact = 0, float_cubic = 0;
  std::array<double, kStages.size()> count{}, robust_by_stage{};
  double filter_left = 0;  // the filter's time on the queries it leaves to the fallback
};

void time_one(const Query& q, Sums& s) {
  const auto robust = [](const Query& x) { return double(robust_ccd(x, &exact::ccd_hit)); };
  const auto filter = [](const Query& x) { return double(robust_ccd_filter(x)); };
  const auto exact = [](const Query& x) { return double(exact::ccd_hit(x)); };
  const auto cubic = [](const Query& x) { return double(float_cubic(x)); };
  const int stage = int(robust_ccd_stage(q));
  const double r = seconds_per_call(robust, q), f = seconds_per_call(filter, q);
  s.robust += r, s.filter += f;
  s.exact += seconds_per_call(exact, q);
  s.float_cubic += seconds_per_call(cubic, q);
  s.count[stage] += 1, s.robust_by_stage[stage] += r;
  if (stage == int(RobustStage::Exact)) s.filter_left += f;
}

void time_stages(benchmark::State& state, const std::vector<Query>& qs) {
  Sums s;
  for (auto _ : state)
    for (const Query& q : qs) time_one(q, s);
  const double n = double(qs.size());
  state.counters["queries"] = n;
  for (std::size_t i = 0; i < kStages.size(); ++i) {
    const std::string name = kStages[i];
    state.counters[name + "_share"] = s.count[i] / n;
    state.counters[name + "_robust_ns"] =
        s.count[i] > 0 ? 1e9 * s.robust_by_stage[i] / s.count[i] : 0;
  }
  const double left = s.count.back();
  state.counters["fallback_filter_ns"] = left > 0 ? 1e9 * s.filter_left / left : 0;
  state.counters["fallback_own_ns"] =
      left > 0 ? 1e9 * (s.robust_by_stage.back() - s.filter_left) / left : 0;
  state.counters["robust_ns"] = 1e9 * s.robust / n;
  state.counters["filter_ns"] = 1e9 * s.filter / n;
  state.counters["exact_ns"] = 1e9 * s.exact / n;
  state.counters["float_cubic_ns"] = 1e9 * s.float_cubic / n;
  state.counters["exact_per_robust"] = s.exact / s.robust;
  state.counters["robust_per_float_cubic"] = s.robust / s.float_cubic;
}

void add(const std::string& name, std::vector<Query> qs) {
  if (qs.empty()) return;
  auto shared = std::make_shared<std::vector<Query>>(std::move(qs));
  benchmark::RegisterBenchmark(("stages/" + name).c_str(),
                               [shared](benchmark::State& state) { time_stages(state, *shared); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

// `fdhcert generate <family> --count <count> --seed <seed>`'s queries.
std::vector<Query> family_queries(const char* family, long count, std::uint64_t seed) {
  std::vector<Query> qs;
  for (const verify::Family& f : verify::all_families())
    if (f.name == family)
      for (long i = 0; i < count; ++i)
        qs.push_back(verify::generate(f, verify::case_seed(seed, i)).query);
  return qs;
}

}  // namespace

void register_robust_stages() {
  std::vector<Query> all, hard, held_out;
  for (auto& [name, set] : sample_sets()) {
    all.insert(all.end(), set.begin(), set.end());
    add("sample/" + name, std::move(set));
  }
  add("sample/all", std::move(all));
  for (const char* family : kHard) {
    std::vector<Query> qs = family_queries(family, 1000, 1);
    hard.insert(hard.end(), qs.begin(), qs.end());
    add(std::string("family/") + family, std::move(qs));
    const std::vector<Query> other = family_queries(family, 2000, 3);
    held_out.insert(held_out.end(), other.begin(), other.end());
  }
  add("hard", std::move(hard));
  add("hard-seed-3", std::move(held_out));
}

}  // namespace fdh::bench
