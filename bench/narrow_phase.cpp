// The narrow phase: every method of the registry on every generator family it applies to,
// 256 cases per family (seeds 0-255, the same on every run), as ns per query.
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/gen/families.hpp"
#include "suites.hpp"

namespace fdh::bench {

void register_narrow_phase() {
  constexpr int kCases = 256;
  for (const verify::Family& fam : verify::all_families()) {
    auto queries = std::make_shared<std::vector<Query>>();
    for (int s = 0; s < kCases; ++s) queries->push_back(verify::generate(fam, s).query);
    for (const verify::Method& m : verify::all_methods()) {
      if (!m.applies_to(queries->front())) continue;
      benchmark::RegisterBenchmark(("narrow/" + m.name + "/" + fam.name).c_str(),
                                   [m, queries](benchmark::State& state) {
                                     long hits = 0;
                                     const auto start = std::chrono::steady_clock::now();
                                     for (auto _ : state)
                                       for (const Query& q : *queries) hits += m.hit(q);
                                     const std::chrono::duration<double, std::nano> ns =
                                         std::chrono::steady_clock::now() - start;
                                     benchmark::DoNotOptimize(hits);
                                     state.counters["ns_per_query"] =
                                         ns.count() /
                                         (double(state.iterations()) * double(queries->size()));
                                   })
          ->MinTime(0.05);
    }
  }
}

}  // namespace fdh::bench
