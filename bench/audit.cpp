// `fdhcert audit`'s engine (verify/audit/) on generated cloth sequences at 100x100 and 500x500
// vertices over a unit square, 2 frames, each vertex moving about 28 edge lengths between them
// (a fall, a drift of 5 edge lengths, a small change of shape); neither touches itself, so the
// audit finds nothing:
// - wavy: a height field with two waves each way (z = 0.05 sin cos): one flat patch for the
//   normal cones, the common case of a falling sheet;
// - folds: a sheet folded into a meander (a sine-generated curve in x-z whose tangent turns up
//   to 108 degrees each way, four waves: overhanging folds), extruded along y.
// Wall time (the audit runs on every core): the first frame (trees built, the static check) and
// the step with the second frame's static check, per vertex; after the run, the step's cost per
// vertex at 500x500 over that at 100x100 (issue 20's target: at most 2 on two cores).
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <ostream>
#include <string>

#include <fmt/format.h>

#include "fdh/audit/auditor.hpp"
#include "suites.hpp"

namespace fdh::bench {
namespace {

// The step's ns per vertex by scene and grid, for the ratios printed after the run.
std::map<std::string, std::map<int, double>>& step_ns_per_vertex() {
  static std::map<std::string, std::map<int, double>> m;
  return m;
}

// The folded sheet: arc length s in [0, 1] along x (the tangent's angle 0.6 pi sin(2 pi (4 s +
// phase))), y in [0, 1].
std::vector<Vec3> folds(int n, double phase) {
  const double h = 1.0 / (n - 1), pi = std::acos(-1.0);
  std::vector<double> cx(n), cz(n);
  for (int c = 1; c < n; ++c) {
    const double theta = 0.6 * pi * std::sin(2 * pi * (4 * (c - 0.5) * h + phase));
    cx[c] = cx[c - 1] + h * std::cos(theta);
    cz[c] = cz[c - 1] + h * std::sin(theta);
  }
  std::vector<Vec3> x(std::size_t(n) * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) x[std::size_t(r) * n + c] = {cx[c], r * h, cz[c]};
  return x;
}

std::vector<Vec3> wavy(int n, double phase) {
  const double h = 1.0 / (n - 1), pi = std::acos(-1.0);
  std::vector<Vec3> x(std::size_t(n) * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      x[std::size_t(r) * n + c] = {
          c * h, r * h, 0.05 * std::sin(4 * pi * (c * h + phase)) * std::cos(4 * pi * r * h)};
  return x;
}

// Frame 0 and frame 1: the second fallen 28 edge lengths, drifted 5 along x, its phase moved
// so that no point moves more than a few edge lengths more (the folds' shape change grows
// along the sheet: 0.25 edge lengths of phase move its far end by about 3).
std::array<std::vector<Vec3>, 2> sequence(const std::string& scene, int n) {
  const double h = 1.0 / (n - 1), phase = 0.25 * h;
  std::array<std::vector<Vec3>, 2> f;
  f[0] = scene == "wavy" ? wavy(n, 0) : folds(n, 0);
  f[1] = scene == "wavy" ? wavy(n, phase) : folds(n, phase);
  for (Vec3& p : f[1]) p = p + Vec3{5 * h, 0, -28 * h};
  return f;
}

audit::Topology grid_topology(int n) {
  audit::Topology t;
  t.cloth_vertices = n * n;
  for (int r = 0; r + 1 < n; ++r)
    for (int c = 0; c + 1 < n; ++c) {
      const int a = r * n + c, b = a + 1, d = a + n, e = d + 1;
      t.cloth.push_back({a, b, e});
      t.cloth.push_back({a, e, d});
    }
  return t;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void audit_sequence(benchmark::State& state, const std::string& scene, int n) {
  const audit::Topology topology = grid_topology(n);
  const auto [x0, x1] = sequence(scene, n);
  double first = 0, step = 0;
  audit::FrameReport last;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    audit::Auditor audit(topology);
    const audit::FrameReport r0 = audit.add_frame(x0, {});
    first += seconds_since(start);
    const auto middle = std::chrono::steady_clock::now();
    last = audit.add_frame(x1, {});
    step += seconds_since(middle);
    benchmark::DoNotOptimize(r0);
  }
  const double it = double(state.iterations()), v = double(n) * n;
  state.counters["first_frame_ms"] = 1e3 * first / it;
  state.counters["step_ms"] = 1e3 * step / it;
  state.counters["step_ns_per_vertex"] = 1e9 * step / it / v;
  state.counters["ccd_candidates"] = double(last.step.candidates);
  state.counters["static_candidates"] = double(last.static_candidates);
  state.counters["violations"] =
      double(last.step.total() + last.self_intersections + last.obstacle_intersections);
  step_ns_per_vertex()[scene][n] = 1e9 * step / it / v;
}

}  // namespace

void register_audit() {
  for (const char* scene : {"wavy", "folds"})
    for (const int n : {100, 500})
      benchmark::RegisterBenchmark(
          ("audit/" + std::string(scene) + "/grid:" + std::to_string(n)).c_str(),
          [scene, n](benchmark::State& st) { audit_sequence(st, scene, n); })
          ->Iterations(n < 500 ? 3 : 1)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
}

void print_audit_ratio(std::ostream& out) {
  for (const auto& [scene, m] : step_ns_per_vertex()) {
    if (m.count(100) == 0 || m.count(500) == 0) continue;
    out << fmt::format(
        "\naudit/{}: a step's cost per vertex, 500x500 / 100x100 = {:.2f} ({:.1f} / {:.1f} ns; "
        "target <= 2)\n",
        scene, m.at(500) / m.at(100), m.at(500), m.at(100));
  }
}

}  // namespace fdh::bench
