#include "fdh/classify/classification_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <sstream>

#include "fdh/check/contact.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/classify/toi_report.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;

std::string kinds(const Classification& c) {
  std::string out;
  const auto add = [&](std::size_t n, const char* what) {
    if (n) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", n, what);
  };
  add(c.static_vf, "static vertex-face");
  add(c.moving_vf, "moving vertex-face");
  add(c.edge_edge, "edge-edge");
  return out.empty() ? "no queries" : out;
}

const char* truth_words(TruthSource truth) {
  switch (truth) {
    case TruthSource::File:
      return "the file's truth";
    case TruthSource::Exact:
      return "exact";
    case TruthSource::Mixed:
      break;
  }
  return "the file's truth where given, else exact";
}

void print_block(std::ostream& os, const std::string& title, const Classification& c,
                 const ReportContext& ctx) {
  os << fmt::format("{}: {}; counted against {}", title, kinds(c), truth_words(c.truth));
  if (ctx.gate_k) os << fmt::format("; paper methods gated by {}-DOP overlap", ctx.gate_k);
  if (ctx.min_distance > 0) os << fmt::format("; asked at minimum separation {}", ctx.min_distance);
  os << fmt::format("\n  {:<16} {:>8} {:>8} {:>8} {:>8} {:>8} {:>12}\n", "method", "TP", "TN", "FP",
                    "FN", "n/a", "ns/query");
  for (const MethodResult& m : c.methods) {
    const Tally& t = m.tally;
    if (t.decided() == 0)
      os << fmt::format("  {:<16} {:>8} {:>8} {:>8} {:>8} {:>8} {:>12}\n", m.name, "n/a", "n/a",
                        "n/a", "n/a", t.na, "n/a");
    else
      os << fmt::format("  {:<16} {:>8} {:>8} {:>8} {:>8} {:>8} {:>12.1f}\n", m.name, t.tp, t.tn,
                        t.fp, t.fn, t.na, t.ns_per_query);
  }
}

Json tally_json(const Tally& t) {
  if (t.decided() == 0)
    return {{"tp", nullptr}, {"tn", nullptr}, {"fp", nullptr},
            {"fn", nullptr}, {"na", t.na},    {"ns_per_query", nullptr}};
  // Three decimals are more than the timing's precision.
  return {{"tp", t.tp}, {"tn", t.tn}, {"fp", t.fp},
          {"fn", t.fn}, {"na", t.na}, {"ns_per_query", std::round(t.ns_per_query * 1e3) / 1e3}};
}

// The method's disagreements with the exact twin, by direction and by what its promise makes
// of them (checker.hpp); null where it applies to nothing.
Json against_exact_json(const MethodResult& m) {
  if (m.tally.decided() == 0) return nullptr;
  const DisagreementTally& d = m.against_exact;
  return {{"misses", d.misses},
          {"false_alarms", d.false_alarms},
          {"broken", d.broken},
          {"allowed", d.allowed}};
}

Json counts_json(const Classification& c) {
  Json methods = Json::object();
  for (const MethodResult& m : c.methods) {
    Json one = tally_json(m.tally);
    one["promise"] = to_string(m.promise);
    one["against_exact"] = against_exact_json(m);
    methods[m.name] = std::move(one);
  }
  return {{"queries", c.queries},
          {"static_vf", c.static_vf},
          {"moving_vf", c.moving_vf},
          {"edge_edge", c.edge_edge},
          {"truth", truth_source_name(c.truth)},
          {"methods", methods}};
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (const char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// The contact and time columns: the exact contact of the query's own decision.
std::pair<std::string, std::string> contact_columns(const Query& q) {
  const TwinContact c = twin_contact(q);
  if (!c.kind.empty()) return {c.kind, c.time_lo};  // static: its kind, and "" without a hit
  if (!c.hit) return {"none", ""};
  return {"moving", c.time_exact() ? c.time_lo : c.time_lo + ".." + c.time_hi};
}

std::string verdict_field(char v) {
  return v == kNotApplicable ? "n/a" : std::to_string(int(v));
}

}  // namespace

void print_table(std::ostream& os, const std::vector<FileClassification>& files,
                 const Classification& total, const ReportContext& ctx) {
  if (files.size() > 1)
    for (const FileClassification& f : files) print_block(os, f.file, f.c, ctx), os << "\n";
  print_block(os, files.size() > 1 ? "total" : files.front().file, total, ctx);
}

Json classification_json(const std::vector<FileClassification>& files, const Classification& total,
                         const ReportContext& ctx) {
  Json j = counts_json(total);
  j["gate"] = ctx.gate_k;
  j["files"] = Json::array();
  for (const FileClassification& f : files) {
    Json one = {{"file", f.file}};
    one.update(counts_json(f.c));
    j["files"].push_back(std::move(one));
  }
  return j;
}

namespace {

std::string where_and_id(const QueryRecord& q) {
  return q.file + ":" + std::to_string(q.line) + " (query " + q.id + ")";
}

// One decimal of a ns is more than the timing's precision.
Json ns_json(double ns) {
  return std::round(ns * 10) / 10;
}

}  // namespace

void print_cpu_times(std::ostream& os, const std::vector<TimeSpread>& spreads,
                     const std::vector<QueryRecord>& queries, int rounds) {
  os << fmt::format(
      "thread CPU time per query, each query timed alone (the least disturbed of {} batches):\n"
      "  {:<16} {:>8} {:>12} {:>12} {:>12}  {}\n",
      rounds, "method", "queries", "median ns", "p90 ns", "max ns", "slowest");
  for (const TimeSpread& s : spreads) {
    if (s.queries == 0)
      os << fmt::format("  {:<16} {:>8} {:>12} {:>12} {:>12}\n", s.method, 0, "n/a", "n/a", "n/a");
    else
      os << fmt::format("  {:<16} {:>8} {:>12.1f} {:>12.1f} {:>12.1f}  {}\n", s.method, s.queries,
                        s.median, s.p90, s.max, where_and_id(queries[s.slowest]));
  }
}

Json cpu_times_json(const std::vector<TimeSpread>& spreads, const std::vector<QueryRecord>& queries,
                    int rounds) {
  Json methods = Json::object();
  for (const TimeSpread& s : spreads) {
    if (s.queries == 0) {
      methods[s.method] = {{"queries", 0},
                           {"median_ns", nullptr},
                           {"p90_ns", nullptr},
                           {"max_ns", nullptr},
                           {"slowest", nullptr}};
      continue;
    }
    methods[s.method] = {{"queries", s.queries},
                         {"median_ns", ns_json(s.median)},
                         {"p90_ns", ns_json(s.p90)},
                         {"max_ns", ns_json(s.max)},
                         {"slowest", where_and_id(queries[s.slowest])}};
  }
  return {{"rounds", rounds}, {"methods", methods}};
}

std::string per_query_csv(const std::vector<QueryRecord>& queries, const Classification& c,
                          const ToiClassification* toi) {
  std::set<std::string> files;
  for (const QueryRecord& q : queries) files.insert(q.file);
  const bool prefix = files.size() > 1;
  std::ostringstream os;
  os << "id,truth";
  for (const MethodResult& m : c.methods) os << ',' << m.name;
  os << ",contact,time" << (toi ? toi_csv_header(*toi) : "") << "\n";
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const QueryRecord& q = queries[i];
    // FILE:LINE is the query's true place (a CSV query's id is its number in the file, which
    // as FILE:ID looked like a line).
    os << csv_field(prefix ? q.file + ":" + std::to_string(q.line) + " " + q.id : q.id) << ','
       << int(c.reference[i]);
    for (const MethodResult& m : c.methods) os << ',' << verdict_field(m.verdict[i]);
    const auto [contact, time] = contact_columns(q.query);
    os << ',' << contact << ',' << time << (toi ? toi_csv_fields(*toi, i) : "") << '\n';
  }
  return os.str();
}

}  // namespace fdh::verify
