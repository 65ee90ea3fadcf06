#include "fdh/suite/report.hpp"

#include <cstdio>
#include <set>

#include <sstream>
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/io/json.hpp"

namespace fdh::verify {
namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (const char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

}  // namespace

namespace {

std::string kinds(const Classification& c) {
  std::string out;
  const auto add = [&](std::size_t n, const char* what) {
    if (n) out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(c.static_vf, "static vertex-face");
  add(c.moving_vf, "moving vertex-face");
  add(c.edge_edge, "edge-edge");
  return out.empty() ? "no queries" : out;
}

void print_block(std::ostream& os, const std::string& title, const Classification& c,
                 const ReportContext& ctx) {
  os << title << ": " << kinds(c) << "; counted against "
     << (c.truth == "file"    ? "the file's truth"
         : c.truth == "exact" ? "exact"
                              : "the file's truth where given, else exact");
  if (ctx.gate_k) os << "; paper methods gated by " << ctx.gate_k << "-DOP overlap";
  os << "\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %-16s %8s %8s %8s %8s %8s %12s\n", "method", "TP", "TN", "FP",
                "FN", "n/a", "ns/query");
  os << buf;
  for (const MethodResult& m : c.methods) {
    const Tally& t = m.tally;
    if (t.decided() == 0)
      std::snprintf(buf, sizeof buf, "  %-16s %8s %8s %8s %8s %8ld %12s\n", m.name.c_str(), "n/a",
                    "n/a", "n/a", "n/a", t.na, "n/a");
    else
      std::snprintf(buf, sizeof buf, "  %-16s %8ld %8ld %8ld %8ld %8ld %12.1f\n", m.name.c_str(),
                    t.tp, t.tn, t.fp, t.fn, t.na, t.ns_per_query);
    os << buf;
  }
}

void print_json_body(std::ostream& os, const Classification& c) {
  os << "\"queries\": " << c.queries << ", \"static_vf\": " << c.static_vf
     << ", \"moving_vf\": " << c.moving_vf << ", \"edge_edge\": " << c.edge_edge
     << ", \"truth\": " << json_string(c.truth) << ", \"methods\": {";
  bool first = true;
  for (const MethodResult& m : c.methods) {
    const Tally& t = m.tally;
    os << (first ? "" : ", ") << json_string(m.name) << ": {";
    if (t.decided() == 0) {
      os << "\"tp\": null, \"tn\": null, \"fp\": null, \"fn\": null, \"na\": " << t.na
         << ", \"ns_per_query\": null}";
    } else {
      char ns[32];
      std::snprintf(ns, sizeof ns, "%.3f", t.ns_per_query);
      os << "\"tp\": " << t.tp << ", \"tn\": " << t.tn << ", \"fp\": " << t.fp
         << ", \"fn\": " << t.fn << ", \"na\": " << t.na << ", \"ns_per_query\": " << ns << "}";
    }
    first = false;
  }
  os << "}";
}

}  // namespace

void print_table(std::ostream& os, const std::vector<FileClassification>& files,
                 const Classification& total, const ReportContext& ctx) {
  if (files.size() > 1)
    for (const FileClassification& f : files) print_block(os, f.file, f.c, ctx), os << "\n";
  print_block(os, files.size() > 1 ? "total" : files.front().file, total, ctx);
}

void print_json(std::ostream& os, const std::vector<FileClassification>& files,
                const Classification& total, const ReportContext& ctx) {
  os << "{";
  print_json_body(os, total);
  os << ", \"gate\": " << ctx.gate_k << ", \"files\": [";
  for (std::size_t i = 0; i < files.size(); ++i) {
    os << (i ? ", " : "") << "{\"file\": " << json_string(files[i].file) << ", ";
    print_json_body(os, files[i].c);
    os << "}";
  }
  os << "]}\n";
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
