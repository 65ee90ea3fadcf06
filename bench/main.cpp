// fdh_bench: `./run bench` (docs/performance.md). Google Benchmark's own options apply
// (--benchmark_filter=REGEX, --benchmark_out=FILE --benchmark_out_format=json, ...); after the
// run, the peers' ratios to ours, the audit's ratio of costs per vertex and the minimum
// separation's ratios (bench/ccd_delta.cpp).
#include <benchmark/benchmark.h>

#include <iostream>
#include <map>
#include <string>

#include "peer_ratios.hpp"
#include "suites.hpp"

namespace {

// The console's report, keeping each run's mean CPU seconds per iteration for the ratios (CPU
// time: on a shared machine, wall time counts the other processes too).
class KeepTimes : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && r.iterations > 0)
        seconds[r.benchmark_name()] = r.cpu_accumulated_time / double(r.iterations);
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> seconds;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  fdh::bench::register_narrow_phase();
  fdh::bench::register_ccd_sample();
  fdh::bench::register_ccd_toi();
  fdh::bench::register_robust_stages();
  fdh::bench::register_ccd_delta();
  fdh::bench::register_frames();
  fdh::bench::register_audit();
  KeepTimes console;
  benchmark::RunSpecifiedBenchmarks(&console);
  fdh::bench::print_peer_ratios(console.seconds, std::cout);
  fdh::bench::print_audit_ratio(std::cout);
  fdh::bench::print_delta_ratios(std::cout);
  benchmark::Shutdown();
  return 0;
}
