// Time of impact against speed: every method that gives a TOI on the moving families'
// queries, how early and how often late against the exact earliest contact.
#include <fmt/format.h>

#include <iterator>
#include <vector>

#include "fdh/check/classify_toi.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/report/measurements.hpp"

namespace fdh::verify {
namespace {

ToiSpeedRow toi_row(const ToiResult& m, const std::string& family) {
  const TimeTally& t = m.tally;
  long early = 0;
  for (const double e : t.early) early += e > kToiWidthAsked;
  return {m.name,        family, t.checked, t.contacts, m.ns_per_query,  t.early_median(),
          t.early_max(), t.late, early,     t.zero,     t.verdict_errors};
}

}  // namespace

std::vector<ToiSpeedRow> toi_speed(long per_family, std::uint64_t seed,
                                   const ProgressSink& progress) {
  const std::vector<Method> methods = toi_methods();
  const std::size_t families = all_families().size();
  std::vector<ToiSpeedRow> rows;
  for (std::size_t k = 0; k < families; ++k) {
    report(progress, {"time of impact against speed", long(k), long(families), "families"});
    const Family& f = all_families()[k];
    if (!f.moving) continue;
    const ToiClassification c =
        classify_toi(family_queries(k, per_family, seed), methods, kToiWidthAsked);
    for (const ToiResult& m : c.methods)
      if (m.tally.checked > 0) rows.push_back(toi_row(m, f.name));
  }
  return rows;
}

std::string toi_speed_csv(const std::vector<ToiSpeedRow>& rows) {
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to,
                 "method,family,queries,contacts,ns_per_query,early_median,early_max,late,early,"
                 "zero,verdict_errors\n");
  for (const ToiSpeedRow& r : rows)
    fmt::format_to(to, "{},{},{},{},{:.6g},{:.6g},{:.6g},{},{},{},{}\n", r.method, r.family,
                   r.queries, r.contacts, r.ns_per_query, r.early_median, r.early_max, r.late,
                   r.early, r.zero, r.verdict_errors);
  return fmt::to_string(out);
}

}  // namespace fdh::verify
