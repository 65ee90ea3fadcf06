#include "fdh/verify/report.hpp"

#include <cstdio>
#include <set>

#include <sstream>
#include "fdh/exact/point_triangle.hpp"
#include "fdh/verify/json.hpp"

namespace fdh::verify {
namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (const char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

}  // namespace

void print_table(std::ostream& os, const Classification& c, const ReportContext& ctx) {
  os << c.queries << " static vertex-face queries, counted against "
     << (c.truth == "file"    ? "the file's truth"
         : c.truth == "exact" ? "exact"
                              : "the file's truth where given, else exact");
  if (ctx.gate_k) os << "; paper methods gated by " << ctx.gate_k << "-DOP overlap";
  if (ctx.skipped) os << "; " << ctx.skipped << " other queries skipped";
  os << "\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "%-16s %8s %8s %8s %8s %12s\n", "method", "TP", "TN", "FP", "FN",
                "ns/query");
  os << buf;
  for (const MethodResult& m : c.methods) {
    const Tally& t = m.tally;
    std::snprintf(buf, sizeof buf, "%-16s %8ld %8ld %8ld %8ld %12.1f\n", m.name.c_str(), t.tp, t.tn,
                  t.fp, t.fn, t.ns_per_query);
    os << buf;
  }
}

void print_json(std::ostream& os, const Classification& c, const ReportContext& ctx) {
  os << "{\"queries\": " << c.queries << ", \"truth\": " << json_string(c.truth)
     << ", \"gate\": " << ctx.gate_k << ", \"skipped\": " << ctx.skipped << ", \"methods\": {";
  bool first = true;
  for (const MethodResult& m : c.methods) {
    const Tally& t = m.tally;
    char ns[32];
    std::snprintf(ns, sizeof ns, "%.3f", t.ns_per_query);
    os << (first ? "" : ", ") << json_string(m.name) << ": {\"tp\": " << t.tp
       << ", \"tn\": " << t.tn << ", \"fp\": " << t.fp << ", \"fn\": " << t.fn
       << ", \"ns_per_query\": " << ns << "}";
    first = false;
  }
  os << "}}\n";
}

std::string per_query_csv(const std::vector<Query>& queries, const Classification& c) {
  std::set<std::string> files;
  for (const Query& q : queries) files.insert(q.file);
  const bool prefix = files.size() > 1;
  std::ostringstream os;
  os << "id,truth";
  for (const MethodResult& m : c.methods) os << ',' << m.name;
  os << ",contact,time\n";
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    os << csv_field(prefix ? q.file + ":" + q.id : q.id) << ',' << int(c.reference[i]);
    for (const MethodResult& m : c.methods) os << ',' << int(m.verdict[i]);
    const exact::PointTriangleContact e =
        exact::point_triangle(q.b0(), q.b1(), q.d(), q.e(), q.f());
    os << ',' << exact::to_string(e.kind) << ',' << e.time << '\n';
  }
  return os.str();
}

}  // namespace fdh::verify
