// The minimum separation δ in the report (issue 30): speed against accuracy per method at δ
// = 0, 2^-40, 2^-20, 2^-10 times each query's own size, and which methods answer right as the
// true least distance approaches D from below and from above.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <random>
#include <vector>

#include "fdh/check/classify.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/report/measurements.hpp"

namespace fdh::verify {
namespace {

// A query's own size: the largest extent of its 8 points along an axis, rounded down to a power
// of two so that δ = 2^-e times it is a double exactly (1 for a query of one point).
double size_of(const Query& q) {
  double extent = 0;
  for (int c = 0; c < 3; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& p : q.x) {
      const double v = c == 0 ? p.x : c == 1 ? p.y : p.z;
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    extent = std::max(extent, hi - lo);
  }
  if (!(extent > 0) || !std::isfinite(extent)) return 1;
  int e = 0;
  std::frexp(extent, &e);  // extent in [2^(e-1), 2^e)
  return std::ldexp(1.0, e - 1);
}

// The speed rows of one kind at one δ: every method that answers it, against the exact twin.
void add_speed_rows(std::vector<MinDistanceSpeedRow>& rows, const std::vector<Query>& qs,
                    int exponent, const char* kind) {
  const Classification c = classify(qs, {}, all_methods());
  for (const MethodResult& m : c.methods) {
    const long n = m.tally.decided();  // n/a where it does not answer δ > 0
    if (n == 0) continue;
    rows.push_back({m.name, exponent, kind, n, m.tally.ns_per_query, double(m.tally.fp) / double(n),
                    double(m.tally.fn) / double(n)});
  }
}

}  // namespace

const std::array<int, 4>& min_distance_exponents() {
  static const std::array<int, 4> e = {0, 40, 20, 10};  // 0: δ = 0
  return e;
}

std::vector<MinDistanceSpeedRow> min_distance_speed(long per_family, std::uint64_t seed,
                                                    const ProgressSink& progress) {
  std::vector<Query> of_kind[2];  // static, moving
  for (std::size_t k = 0; k < all_families().size(); ++k)
    for (const Query& q : family_queries(k, per_family, seed))
      of_kind[all_families()[k].moving].push_back(q);
  std::vector<MinDistanceSpeedRow> rows;
  long done = 0;
  for (const int e : min_distance_exponents())
    for (int kind = 0; kind < 2; ++kind) {
      report(progress, {"minimum separation: speed", done++, 8, "runs"});
      std::vector<Query> qs = of_kind[kind];
      for (Query& q : qs) q.min_distance = e == 0 ? 0 : std::ldexp(size_of(q), -e);
      add_speed_rows(rows, qs, e, kind ? "moving" : "static");
    }
  return rows;
}

std::string min_distance_speed_csv(const std::vector<MinDistanceSpeedRow>& rows) {
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out),
                 "method,delta,kind,queries,ns_per_query,fp_rate,fn_rate\n");
  for (const MinDistanceSpeedRow& r : rows)
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{:.6g},{:.6g},{:.6g}\n", r.method,
                   r.exponent == 0 ? std::string("0") : fmt::format("2^-{}", r.exponent), r.kind,
                   r.queries, r.ns_per_query, r.fp_rate, r.fn_rate);
  return fmt::to_string(out);
}

}  // namespace fdh::verify
