// The cost of a frame on the table scene (corpus/scenes/table.scene, its step made stable at
// each grid as `fdhcert simulate` does) from 15x15 to 500x500 particles, without and with the
// self-collision pass: the first frames of the fall, fewer at the large grids. Counters: ms per
// frame of each part and µs per particle per frame.
#include <benchmark/benchmark.h>

#include <string>

#include "cloth_on_table.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/cloth/simulation.hpp"
#include "fdh/exact/ccd.hpp"
#include "suites.hpp"

namespace fdh::bench {
namespace {

void frame(benchmark::State& state, int grid, bool self) {
  cloth::Scene scene = shipped_scene("table", grid);
  scene.self_collision = self;
  cloth::Simulation sim(scene, verify::narrow_phase_named("robust"), 18, 0, &exact::ccd_hit);
  cloth::FrameTimes sum;
  for (auto _ : state) {
    sim.step();
    sum += sim.times();
  }
  const double per = 1e3 / double(state.iterations());
  state.counters["springs_ms"] = per * sum.springs;
  state.counters["refit_ms"] = per * sum.refit;
  state.counters["traversal_ms"] = per * sum.traversal;
  state.counters["narrow_ms"] = per * sum.narrow;
  state.counters["response_ms"] = per * sum.response;
  state.counters["self_ms"] = per * sum.self;
  state.counters["us_per_particle"] = 1e3 * per * sum.total() / (double(grid) * grid);
  state.counters["self_us_per_particle"] = 1e3 * per * sum.self / (double(grid) * grid);
}

}  // namespace

// Frames per grid: about a second of work at the largest.
void register_frames() {
  const std::pair<int, int> runs[] = {{15, 400}, {25, 300}, {50, 200},
                                      {100, 60}, {200, 20}, {500, 4}};
  for (const int self : {0, 1})
    for (const auto& [grid, frames] : runs)
      benchmark::RegisterBenchmark(
          ("frame/grid:" + std::to_string(grid) + "/self:" + std::to_string(self)).c_str(),
          [grid = grid, self](benchmark::State& st) { frame(st, grid, self != 0); })
          ->Iterations(frames)
          ->Unit(benchmark::kMillisecond);
}

}  // namespace fdh::bench
