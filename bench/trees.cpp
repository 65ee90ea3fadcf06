// Our FDH tree on the cloth over the table, per k and grid: build (the cloth's particles, swept
// over the step), refit, and traversal against the table's tree (every slab at once, as the
// simulation does).
#include <benchmark/benchmark.h>

#include "cloth_on_table.hpp"
#include "fdh/bvh.hpp"
#include "fdh/check/registry.hpp"

namespace fdh::bench {
namespace {

template <int K>
void tree_build(benchmark::State& state) {
  const ClothOnTable& c = cloth_on_table(int(state.range(0)));
  const std::vector<Tri> prims = point_prims(int(c.x0.size()));
  for (auto _ : state) {
    Bvh<K> t(prims, c.x0, c.x1);
    benchmark::DoNotOptimize(t.nodes().data());
  }
  state.counters["particles"] = double(c.x0.size());
}

template <int K>
void tree_refit(benchmark::State& state) {
  const ClothOnTable& c = cloth_on_table(int(state.range(0)));
  Bvh<K> t(point_prims(int(c.x0.size())), c.x0, c.x1);
  for (auto _ : state) {
    t.refit(c.x0, c.x1);
    benchmark::DoNotOptimize(t.nodes().data());
  }
  state.counters["particles"] = double(c.x0.size());
}

template <int K>
void tree_traverse(benchmark::State& state) {
  const ClothOnTable& c = cloth_on_table(int(state.range(0)));
  const Bvh<K> cloth(point_prims(int(c.x0.size())), c.x0, c.x1);
  const Bvh<K> table(c.table.tris, c.table.x);
  std::vector<std::pair<int, int>> pairs;
  for (auto _ : state) {
    pairs.clear();
    traverse(cloth, table, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = double(pairs.size());
  // The box tests of one traversal (untimed: the same descent with a counting test).
  long tests = 0;
  std::vector<std::pair<int, int>> stack = {{0, 0}}, again;
  descend_pairs(cloth, table, stack, again, [&tests](const Kdop<K>& a, const Kdop<K>& b) {
    ++tests;
    return overlap(a, b);
  });
  state.counters["box_tests"] = double(tests);
}

// Traversal and the narrow phase (robust, as the simulation runs it) on every candidate pair:
// the work FCL's collide does, for the ratio to it.
void tree_collide(benchmark::State& state) {
  const ClothOnTable& c = cloth_on_table(int(state.range(0)));
  const Bvh<18> cloth(point_prims(int(c.x0.size())), c.x0, c.x1);
  const Bvh<18> table(c.table.tris, c.table.x);
  const PointTriangleTest narrow = verify::narrow_phase_named("robust");
  std::vector<std::pair<int, int>> pairs;
  long hits = 0;
  for (auto _ : state) {
    pairs.clear();
    traverse(cloth, table, pairs);
    hits = 0;
    for (const auto& [p, t] : pairs) {
      const Tri& f = c.table.tris[t];
      hits += narrow(c.x0[p], c.x1[p], c.table.x[f[0]], c.table.x[f[1]], c.table.x[f[2]]);
    }
  }
  state.counters["hits"] = double(hits);
}
BENCHMARK(tree_collide)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);

void grids(benchmark::internal::Benchmark* b) {
  for (const int g : kTreeGrids) b->Arg(g);
  b->Unit(benchmark::kMicrosecond);
}

#define FDH_TREE_BENCH(K)                          \
  BENCHMARK_TEMPLATE(tree_build, K)->Apply(grids); \
  BENCHMARK_TEMPLATE(tree_refit, K)->Apply(grids); \
  BENCHMARK_TEMPLATE(tree_traverse, K)->Apply(grids);

FDH_TREE_BENCH(6)
FDH_TREE_BENCH(14)
FDH_TREE_BENCH(18)
FDH_TREE_BENCH(26)

}  // namespace
}  // namespace fdh::bench
