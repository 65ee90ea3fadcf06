// The time of one call of a method on one query, for the benchmarks that time each query on its
// own (toi/, delta/): thread CPU time (a busy machine's waiting does not count), the least of
// three batches of back-to-back calls lasting 2 µs or more.
#pragma once

#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>

#include "fdh/query.hpp"

namespace fdh::bench {

inline double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Seconds per call of `f` on q: the least of three batches.
template <class F>
double seconds_per_call(const F& f, const Query& q) {
  int reps = 1;
  double best = 1e300;
  for (int batch = 0; batch < 3;) {
    double sink = 0;
    const double start = thread_seconds();
    for (int r = 0; r < reps; ++r) sink += f(q);
    const double s = thread_seconds() - start;
    benchmark::DoNotOptimize(sink);
    if (s < 2e-6 && reps < 4096) {
      reps *= 4;
      continue;
    }
    best = std::min(best, s / reps);
    ++batch;
  }
  return best;
}

}  // namespace fdh::bench
