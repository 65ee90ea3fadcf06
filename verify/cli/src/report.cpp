// fdhcert report: certificate, measurements, charts and report.md in one folder.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "commands.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/suite/certify.hpp"
#include "fdh/io/charts.hpp"
#include "fdh/suite/measurements.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

const char* const kReportHelp =
    R"(usage: fdhcert report [--quick] [--out DIR] [--corpus DIR] [--seed S]
                      [--per-family N] [--soups N] [EXTRA FILES...]

The verification report, as `./run verify` makes it (into docs/report):
  DIR/certificate.json, .md   fdhcert certify over the corpus, fuzzed cases
                              and the EXTRA FILES
  DIR/data/*.csv              the measurements behind the charts
  DIR/speed_accuracy.png/svg  ns per query against FP and FN rates, one point
                              per method and family, with the Pareto front
  DIR/stability.png/svg       failure rate of each method as the motion angle,
                              the distance to an edge, the distance from the
                              origin and the triangle's aspect go to their limits
  DIR/kdop_k.png/svg          FDH tree build, refit and traversal time against
                              candidate pairs, k = 6, 14, 18, 26
  DIR/report.md               all of it, with tables
Charts need gnuplot (Debian: gnuplot-nox). Exit status 1 if the certificate
finds a violation (the report is written all the same).

  --quick          smaller samples (a quick certificate, 100 queries per family
                   and point): for a first look, not for the committed report
  --out DIR        default: report
  --corpus DIR, --seed S, --per-family N, --soups N: as for certify
  -h, --help       this text
)";

using Table = std::vector<std::vector<std::string>>;

Table parse_csv(const std::string& text) {
  Table t;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> row;
    std::istringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) row.push_back(cell);
    t.push_back(row);
  }
  return t;
}

std::string fmt(double v, const char* f = "%.3g") {
  char buf[32];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string speed_table(const Table& rows) {
  struct Acc {
    std::vector<double> ns;
    double fp = 0, fn = 0;
    int families = 0, clean = 0;
  };
  std::map<std::string, Acc> by;
  std::vector<std::string> order;
  for (const auto& r : rows) {
    if (!by.count(r[0])) order.push_back(r[0]);
    Acc& a = by[r[0]];
    a.ns.push_back(std::stod(r[3]));
    a.fp += std::stod(r[4]);
    a.fn += std::stod(r[5]);
    ++a.families;
    a.clean += std::stod(r[4]) == 0 && std::stod(r[5]) == 0;
  }
  std::ostringstream os;
  os << "| method | ns/query (median over families) | FP rate (mean) | FN rate (mean) | families "
        "with no error |\n|---|---|---|---|---|\n";
  for (const std::string& m : order) {
    Acc& a = by[m];
    std::nth_element(a.ns.begin(), a.ns.begin() + a.ns.size() / 2, a.ns.end());
    os << "| " << m << " | " << fmt(a.ns[a.ns.size() / 2], "%.1f") << " | "
       << fmt(a.fp / a.families) << " | " << fmt(a.fn / a.families) << " | " << a.clean << " of "
       << a.families << " |\n";
  }
  return os.str();
}

std::string stability_table(const Table& rows) {
  // For each sweep and method: the first parameter with failures, and the worst rate.
  std::map<std::pair<std::string, std::string>, std::pair<int, double>> s;
  std::vector<std::string> sweeps, methods;
  for (const auto& r : rows) {
    const auto key = std::make_pair(r[0], r[2]);
    if (std::find(sweeps.begin(), sweeps.end(), r[0]) == sweeps.end()) sweeps.push_back(r[0]);
    if (std::find(methods.begin(), methods.end(), r[2]) == methods.end()) methods.push_back(r[2]);
    auto& v = s.emplace(key, std::make_pair(-1, 0.0)).first->second;
    const double rate = std::stod(r[3]);
    if (rate > 0 && v.first < 0) v.first = std::stoi(r[1]);
    v.second = std::max(v.second, rate);
  }
  std::ostringstream os;
  os << "| sweep | ";
  for (const std::string& m : methods) os << m << " | ";
  os << "\n|---|";
  for (std::size_t i = 0; i < methods.size(); ++i) os << "---|";
  os << "\n";
  for (const std::string& sw : sweeps) {
    os << "| " << sw << " | ";
    for (const std::string& m : methods) {
      const auto& v = s[{sw, m}];
      os << (v.first < 0 ? std::string("never wrong")
                         : "wrong from p = " + std::to_string(v.first) + ", worst " + fmt(v.second))
         << " | ";
    }
    os << "\n";
  }
  return os.str();
}

std::string kdop_table(const Table& rows) {
  std::ostringstream os;
  os << "| k | cloth grid | cloth / obstacle triangles | build ms | refit ms | traverse ms | "
        "candidate pairs |\n|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    os << "| " << r[0] << " | " << r[1] << "×" << r[1] << " | " << r[2] << " / " << r[3] << " | "
       << fmt(std::stod(r[4])) << " | " << fmt(std::stod(r[5])) << " | " << fmt(std::stod(r[6]))
       << " | " << r[7] << " |\n";
  return os.str();
}

}  // namespace

int report_command(const Args& args, std::ostream& out, std::ostream& err) {
  CertifyOptions opt;
  opt.out_dir = "report";
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kReportHelp;
      return 0;
    } else if (!read_certify_option(a, opt)) {
      a.unknown("report");
    }
  }
  const fs::path dir(opt.out_dir);
  fs::create_directories(dir / "data");
  const long sample = opt.quick ? 100 : 1000;

  out << "report: certificate ..." << std::endl;
  const Certificate cert = certify(opt);
  write_certificate(cert);
  const std::string cert_md = certificate_markdown(cert);

  out << "report: speed against accuracy ..." << std::endl;
  const std::string speed = speed_accuracy_csv(sample, opt.seed);
  write_file_atomically((dir / "data/speed_accuracy.csv").string(), speed);
  write_file_atomically((dir / "data/pareto.csv").string(), pareto_csv(speed));
  out << "report: stability sweeps ..." << std::endl;
  const std::string stability = stability_csv(opt.quick ? 100 : 400, opt.seed);
  write_file_atomically((dir / "data/stability.csv").string(), stability);
  out << "report: FDH k ..." << std::endl;
  // One block per grid size; a blank line between blocks keeps gnuplot from joining them.
  std::string kdop = kdop_tree_csv(30);
  for (const int grid : {50, 100}) {
    const std::string rows = kdop_tree_csv(grid);
    kdop += "\n" + rows.substr(rows.find('\n') + 1);
  }
  write_file_atomically((dir / "data/kdop_tree.csv").string(), kdop);
  out << "report: charts ..." << std::endl;
  draw_charts(dir.string());

  std::ostringstream md;
  md << "# fdhcert verification report\n\n"
     << "Written by `./run verify` (`fdhcert report --out " << opt.out_dir << "`) at commit `"
     << cert.commit << "`" << (opt.quick ? ", quick samples" : "")
     << ". Every number here is measured by that run; times vary between runs and machines, so "
        "compare rows within this report. Data: `data/*.csv`.\n\n"
     << "## Certificate\n\n"
     << cert_md.substr(cert_md.find('\n') + 1) << "\n"
     << "## Speed against accuracy\n\n"
     << "Every method on " << sample
     << " queries of each generator family (docs/methods.md), rates against `exact`. One point "
        "per method and family; the black steps are the Pareto front of time against error "
        "rate.\n\n![speed against accuracy](speed_accuracy.svg)\n\n"
     << speed_table(parse_csv(speed)) << "\n"
     << "## Where methods break\n\n"
     << "The share of queries each method gets wrong (against `exact`) as one parameter goes to "
        "its degenerate limit: the angle between the motion and the plane (2^-p), the distance "
        "from the crossing to an edge (2^-p, inside or outside), the distance from the origin "
        "(2^p), and the triangle's height over its base (2^-p). "
     << (opt.quick ? 100 : 400)
     << " queries per point. The paper's readings fail at a constant rate because they have no "
        "inside test; what matters is where a curve rises.\n\n![stability](stability.svg)\n\n"
     << stability_table(parse_csv(stability)) << "\n"
     << "## FDH k\n\n"
     << "A cloth grid draped over a triangulated sphere (2304 triangles), the cloth tree swept "
        "over one step, traversal with the early-out slab along the fall. More directions cost "
        "more per box and cull more pairs.\n\n![FDH k](kdop_k.svg)\n\n"
     << kdop_table(parse_csv(kdop));
  write_file_atomically((dir / "report.md").string(), md.str());

  out << "report: wrote " << (dir / "report.md").string() << "; certificate "
      << (cert.certified() ? "certified" : "VIOLATED") << "\n";
  if (!cert.certified()) {
    err << "fdhcert: certify: " << cert.first_violation << "\n";
    return 1;
  }
  return 0;
}

}  // namespace fdh::verify
