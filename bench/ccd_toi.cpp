// robust's time of impact (fdh/ccd/toi.hpp) beside its verdict alone, in the same run: per set of
// the benchmark sample (FDH_CCD_SAMPLE, skipped without one), all of it, each moving
// generator family (256 cases) and the hard ones together: ns per query of `robust` (the
// registry's method: the verdict only), of robust_ccd_toi at w = 2^-30 and 2^-50, and of
// float_cubic_toi, with the ratios of issue 19's targets as counters (toi30_per_verdict,
// w50_per_w30: means over the queries). Each query is timed on its own, the four in turn (each
// query starting with the next), as thread CPU time (a busy machine's waiting does not count), the
// least of three batches of back-to-back calls lasting 2 µs or more.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "fdh/ccd/float_cubic.hpp"
#include "fdh/ccd/toi.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/io/query_io.hpp"
#include "per_call.hpp"
#include "sample_sets.hpp"
#include "suites.hpp"

namespace fdh::bench {
namespace {

// The methods timed, in this order on each query.
struct Timed {
  const char* name;
  std::function<double(const Query&)> run;
};
std::vector<Timed> timed_methods() {
  verify::Method robust;
  for (const verify::Method& m : verify::all_methods())
    if (m.name == "robust") robust = m;
  const auto toi = [](double w) {
    return [w](const Query& q) { return robust_ccd_toi(q, w, &exact::ccd_toi).t_lo; };
  };
  return {{"verdict", [robust](const Query& q) { return double(robust.hit(q)); }},
          {"toi30", toi(0x1p-30)},
          {"toi50", toi(0x1p-50)},
          {"float_cubic_toi", [](const Query& q) { return float_cubic_toi(q).t_lo; }}};
}

void time_toi(benchmark::State& state, const std::vector<Query>& qs) {
  const std::vector<Timed> methods = timed_methods();
  std::vector<double> total(methods.size(), 0);
  // The first method on a query meets it in a colder cache: each query starts with the next.
  for (auto _ : state)
    for (std::size_t i = 0; i < qs.size(); ++i)
      for (std::size_t j = 0; j < methods.size(); ++j) {
        const std::size_t m = (i + j) % methods.size();
        total[m] += seconds_per_call(methods[m].run, qs[i]);
      }
  const double n = double(qs.size());
  state.counters["queries"] = n;
  for (std::size_t m = 0; m < methods.size(); ++m)
    state.counters[std::string(methods[m].name) + "_ns"] = 1e9 * total[m] / n;
  state.counters["toi30_per_verdict"] = total[1] / total[0];
  state.counters["toi50_per_verdict"] = total[2] / total[0];
  state.counters["w50_per_w30"] = total[2] / total[1];
}

void add(const std::string& name, std::vector<Query> qs) {
  if (qs.empty()) return;
  auto shared = std::make_shared<std::vector<Query>>(std::move(qs));
  benchmark::RegisterBenchmark(("toi/" + name).c_str(),
                               [shared](benchmark::State& state) { time_toi(state, *shared); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

// The families of the speed targets in docs/methods.md: made hard by construction.
bool is_hard(const std::string& family) {
  for (const char* h : {"hourglass", "two-crossings", "coplanar", "sliding-on-edge",
                        "parallel-edges", "degenerate-edge"})
    if (family == h) return true;
  return false;
}

}  // namespace

void register_ccd_toi() {
  std::vector<Query> all;
  for (auto& [name, set] : sample_sets()) {
    all.insert(all.end(), set.begin(), set.end());
    add("sample/" + name, std::move(set));
  }
  add("sample/all", std::move(all));
  std::vector<Query> hard;
  for (const verify::Family& fam : verify::all_families()) {
    if (!fam.moving) continue;
    std::vector<Query> qs;
    for (int s = 0; s < 256; ++s) qs.push_back(verify::generate(fam, s).query);
    if (is_hard(fam.name)) hard.insert(hard.end(), qs.begin(), qs.end());
    add("family/" + fam.name, std::move(qs));
  }
  add("family/hard", std::move(hard));
}

}  // namespace fdh::bench
