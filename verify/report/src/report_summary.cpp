#include "fdh/report/report_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

#include "fdh/check/registry.hpp"

namespace fdh::verify {
namespace {

using Out = std::back_insert_iterator<fmt::memory_buffer>;

// One method over the families of one kind: its counts (rate × queries, which the rates came
// from) and the median of its ns per query over the families.
struct KindTotal {
  long queries = 0, fp = 0, fn = 0;
  double median_ns = 0;
  bool measured() const { return queries > 0; }
};

KindTotal kind_total(const std::vector<SpeedAccuracyRow>& rows, const std::string& method,
                     const std::string& kind) {
  KindTotal t;
  std::vector<double> ns;
  for (const SpeedAccuracyRow& r : rows) {
    if (r.method != method || r.kind != kind) continue;
    t.queries += r.queries;
    t.fp += std::lround(r.fp_rate * double(r.queries));
    t.fn += std::lround(r.fn_rate * double(r.queries));
    ns.push_back(r.ns_per_query);
  }
  if (ns.empty()) return t;
  std::nth_element(ns.begin(), ns.begin() + ns.size() / 2, ns.end());
  t.median_ns = ns[ns.size() / 2];
  return t;
}

std::string kind_cells(const KindTotal& t) {
  if (!t.measured()) return "0 | – | – | –";
  return fmt::format("{} | {} | {} | {:.0f}", t.queries, t.fp, t.fn, t.median_ns);
}

// The promise a method of the registry makes ("exact twin" for the twin itself).
std::string promise_of(const std::string& method) {
  for (const Method& m : all_methods())
    if (m.name == method) return m.is_twin ? "exact twin" : to_string(m.promise);
  return "none";
}

void method_table(Out to, const Report& r) {
  const auto& speed = r.measurements.speed;
  fmt::format_to(
      to,
      "| method | promise | static: queries | FP | FN | ns/query | moving: queries | FP | "
      "FN | ns/query |\n|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> methods;
  for (const SpeedAccuracyRow& row : speed)
    if (std::find(methods.begin(), methods.end(), row.method) == methods.end())
      methods.push_back(row.method);
  for (const std::string& m : methods)
    fmt::format_to(to, "| `{}` | {} | {} | {} |\n", m, promise_of(m),
                   kind_cells(kind_total(speed, m, "static")),
                   kind_cells(kind_total(speed, m, "moving")));
}

void box_table(Out to, const PeersReport& p) {
  fmt::format_to(to,
                 "| library | bounding volume | k | promise | containment: points outside the "
                 "box | overlap: touching pairs missed |\n|---|---|---|---|---|---|\n");
  for (const PeerRow& row : p.rows)
    fmt::format_to(to, "| {} | `{}` | {} | {} | {} of {} sets | {} of {} pairs |\n", row.library,
                   row.method, row.k, to_string(row.promise), row.containment.violations,
                   row.containment.checked, row.overlap.violations, row.overlap.exact_overlaps);
}

}  // namespace

std::string report_summary(const Report& report) {
  const Certificate& c = report.certificate;
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to,
                 "{}: {} checks, {} violations ({} corpus, {} fuzzed, {} scene, {} extra "
                 "queries; {} soup pairs)\n",
                 c.certified() ? "certified" : "VIOLATED", c.checks(), c.violations(),
                 c.corpus_queries, c.fuzzed_queries, c.scene_queries, c.extra_queries,
                 c.options.soups);
  std::vector<std::string> held;
  for (const PromiseCheck& p : c.promises)
    held.push_back(
        fmt::format("{} {} {}/{}", p.method, to_string(p.decision), p.violations, p.checked));
  for (const TimePromiseCheck& t : c.times)
    held.push_back(fmt::format("{} {} {}/{}", t.method, to_string(t.decision), t.tally.broken,
                               t.tally.checked));
  fmt::format_to(to, "promises (violations/queries): {}\n", fmt::join(held, ", "));
  std::vector<std::string> changed;
  for (const MetamorphicCheck& m : c.metamorphic)
    changed.push_back(fmt::format("{} {}/{}", m.method, m.violations, m.checked));
  fmt::format_to(to, "metamorphic (verdicts changed/transformed queries): {}\n",
                 fmt::join(changed, ", "));
  std::map<std::string, std::pair<long, long>> peers;  // library: violations, checks
  std::vector<std::string> libraries;
  for (const PeerRow& row : c.peers.rows) {
    if (!peers.count(row.library)) libraries.push_back(row.library);
    auto& [bad, all] = peers[row.library];
    bad += row.containment.violations + row.overlap.violations;
    all += row.containment.checked + row.overlap.checked;
  }
  std::vector<std::string> per_library;
  for (const std::string& l : libraries)
    per_library.push_back(fmt::format("{} {}/{}", l, peers[l].first, peers[l].second));
  if (!per_library.empty())
    fmt::format_to(to, "bounding volumes (violations/checks; peers counted, not held): {}\n",
                   fmt::join(per_library, ", "));
  return fmt::to_string(out);
}

std::string glance_markdown(const Report& report) {
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to,
                 "Every method on the same {} queries of each generator family ({} static and "
                 "{} moving families): the queries each method applies to, its FP and FN "
                 "against the exact twin summed over the families, and the median over the "
                 "families of its ns per query (this run).\n\n",
                 report.measurements.per_family, report.certificate.families.size(),
                 report.certificate.moving_families.size());
  method_table(to, report);
  if (report.certificate.peers.rows.empty()) return fmt::to_string(out);
  fmt::format_to(to,
                 "\nBounding volumes on the same random point sets and pairs of exactly touching "
                 "point sets (the certificate's peers section, docs/peers.md):\n\n");
  box_table(to, report.certificate.peers);
  return fmt::to_string(out);
}

}  // namespace fdh::verify
