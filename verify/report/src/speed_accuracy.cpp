// Speed against accuracy: every method on every generator family, and the Pareto fronts.
#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <vector>

#include "fdh/check/classify.hpp"
#include "fdh/gen/case_seed.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/report/measurements.hpp"

namespace fdh::verify {

std::vector<Query> family_queries(std::size_t family, long per_family, std::uint64_t seed) {
  const Family& f = all_families().at(family);
  const std::uint64_t stream = family + 1;
  std::vector<Query> qs;
  for (long i = 0; i < per_family; ++i)
    qs.push_back(generate(f, case_seed(seed * 1000 + stream, i)).query);
  return qs;
}

std::vector<SpeedAccuracyRow> speed_accuracy(long per_family, std::uint64_t seed,
                                             const ProgressSink& progress) {
  std::vector<SpeedAccuracyRow> rows;
  const std::vector<Method> methods = all_methods();
  const std::size_t families = all_families().size();
  for (std::size_t k = 0; k < families; ++k) {
    const Family& f = all_families()[k];
    report(progress, {"speed against accuracy", long(k), long(families), "families"});
    const Classification c = classify(family_queries(k, per_family, seed), {}, methods);
    for (const MethodResult& m : c.methods) {
      const long n = m.tally.decided();  // the queries it applies to
      if (n == 0) continue;
      rows.push_back({m.name, f.name, n, m.tally.ns_per_query, double(m.tally.fp) / double(n),
                      double(m.tally.fn) / double(n), f.moving ? "moving" : "static"});
    }
  }
  return rows;
}

std::vector<SpeedAccuracyRow> pareto_front(const std::vector<SpeedAccuracyRow>& rows) {
  std::vector<SpeedAccuracyRow> pts = rows;
  std::sort(pts.begin(), pts.end(), [](const SpeedAccuracyRow& a, const SpeedAccuracyRow& b) {
    return a.ns_per_query < b.ns_per_query ||
           (a.ns_per_query == b.ns_per_query && a.error_rate() < b.error_rate());
  });
  std::vector<SpeedAccuracyRow> front;
  double best = 2;  // above any error rate
  for (const SpeedAccuracyRow& p : pts)
    if (p.error_rate() < best) {
      best = p.error_rate();
      front.push_back(p);
    }
  return front;
}

std::vector<SpeedAccuracyRow> pareto_fronts(const std::vector<SpeedAccuracyRow>& rows) {
  std::vector<SpeedAccuracyRow> fronts;
  for (const char* kind : {"static", "moving"}) {
    std::vector<SpeedAccuracyRow> of_kind;
    std::copy_if(rows.begin(), rows.end(), std::back_inserter(of_kind),
                 [&](const SpeedAccuracyRow& r) { return r.kind == kind; });
    const std::vector<SpeedAccuracyRow> front = pareto_front(of_kind);
    fronts.insert(fronts.end(), front.begin(), front.end());
  }
  return fronts;
}

std::string speed_accuracy_csv(const std::vector<SpeedAccuracyRow>& rows) {
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out),
                 "method,family,queries,ns_per_query,fp_rate,fn_rate,kind\n");
  for (const SpeedAccuracyRow& r : rows)
    fmt::format_to(std::back_inserter(out), "{},{},{},{:.6g},{:.6g},{:.6g},{}\n", r.method,
                   r.family, r.queries, r.ns_per_query, r.fp_rate, r.fn_rate, r.kind);
  return fmt::to_string(out);
}

std::string pareto_csv(const std::vector<SpeedAccuracyRow>& front) {
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out), "method,family,ns_per_query,error_rate,kind\n");
  for (const SpeedAccuracyRow& r : front)
    fmt::format_to(std::back_inserter(out), "{},{},{:.6g},{:.6g},{}\n", r.method, r.family,
                   r.ns_per_query, r.error_rate(), r.kind);
  return fmt::to_string(out);
}

}  // namespace fdh::verify
