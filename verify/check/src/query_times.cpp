#include "fdh/check/query_times.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fdh::verify {
namespace {

// Thread CPU time in ns: not advanced while the thread waits for a core on a shared machine.
double cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

// ns per call over `calls` calls of m on q.
double batch_ns(const Method& m, const Query& q, long calls) {
  volatile bool sink = false;
  const double start = cpu_ns();
  for (long c = 0; c < calls; ++c) sink = m.hit(q);
  (void)sink;
  return (cpu_ns() - start) / double(calls);
}

// Calls per batch: enough for about 50 us, the clock's own cost (a system call) about 1 %.
// Doubled from one call until a batch fills that: sized by a single first call, which is slow
// (cold caches), a fast method's batch was so short that the clock's cost counted many times.
long batch_size(const Method& m, const Query& q) {
  long calls = 1;
  while (calls < 100000 && batch_ns(m, q, calls) * double(calls) < 50000.0) calls *= 2;
  return calls;
}

}  // namespace

std::vector<std::vector<double>> time_each_query(const std::vector<Query>& queries,
                                                 const std::vector<Method>& methods, int rounds) {
  std::vector<std::vector<double>> out(methods.size(), std::vector<double>(queries.size(), 0));
  std::vector<long> calls(methods.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    for (std::size_t m = 0; m < methods.size(); ++m) {
      if (!methods[m].applies_to(q)) continue;
      calls[m] = batch_size(methods[m], q);
      out[m][i] = std::numeric_limits<double>::infinity();
    }
    for (int r = 0; r < rounds; ++r)  // the methods take turns: drifts hit them alike
      for (std::size_t m = 0; m < methods.size(); ++m)
        if (methods[m].applies_to(q))
          out[m][i] = std::min(out[m][i], batch_ns(methods[m], q, calls[m]));
  }
  return out;
}

std::vector<TimeRatio> time_ratios(const std::vector<Query>& queries,
                                   const std::vector<std::vector<double>>& times,
                                   const std::vector<Method>& methods, std::size_t base,
                                   double limit) {
  std::vector<TimeRatio> out;
  for (std::size_t m = 0; m < methods.size(); ++m)
    for (const Decision d : kQueryDecisions) {
      TimeRatio r{methods[m].name, d};
      std::vector<double> all;
      for (std::size_t i = 0; i < queries.size(); ++i) {
        if (decision_of(queries[i]) != d || times[m][i] <= 0 || times[base][i] <= 0) continue;
        const double x = times[m][i] / times[base][i];
        if (all.empty() || x > r.max) r.max = x, r.worst = i;
        r.over += x > limit;
        all.push_back(x);
      }
      if (all.empty()) continue;
      r.queries = all.size();
      std::nth_element(all.begin(), all.begin() + long(all.size() / 2), all.end());
      r.median = all[all.size() / 2];
      out.push_back(r);
    }
  return out;
}

std::vector<TimeSpread> time_spreads(const std::vector<std::vector<double>>& times,
                                     const std::vector<Method>& methods) {
  std::vector<TimeSpread> out;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    TimeSpread s{methods[m].name};
    std::vector<double> all;
    for (std::size_t i = 0; i < times[m].size(); ++i) {
      const double t = times[m][i];
      if (t <= 0) continue;
      if (all.empty() || t > s.max) s.max = t, s.slowest = i;
      all.push_back(t);
    }
    s.queries = all.size();
    if (!all.empty()) {
      std::sort(all.begin(), all.end());
      // Nearest rank: the ceil(p n)-th smallest, so p = 1/2 is the lower median.
      const auto rank = [&](std::size_t percent) {
        return all[(percent * all.size() + 99) / 100 - 1];
      };
      s.median = rank(50), s.p90 = rank(90);
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace fdh::verify
