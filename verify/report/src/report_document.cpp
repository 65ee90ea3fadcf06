#include "fdh/report/report_document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <map>

#include "fdh/os/atomic_file.hpp"
#include "fdh/report/report_html.hpp"
#include "fdh/report/report_summary.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using Out = std::back_insert_iterator<fmt::memory_buffer>;

// The distinct values of a field, in the order they first appear.
template <class Row, class Field>
std::vector<std::string> first_seen(const std::vector<Row>& rows, Field Row::*field) {
  std::vector<std::string> out;
  for (const Row& r : rows)
    if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
  return out;
}

// One line per method of the rows of one kind of family ("static" or "moving").
void speed_table(Out to, const std::vector<SpeedAccuracyRow>& all, const std::string& kind) {
  std::vector<SpeedAccuracyRow> rows;
  std::copy_if(all.begin(), all.end(), std::back_inserter(rows),
               [&](const SpeedAccuracyRow& r) { return r.kind == kind; });
  fmt::format_to(to,
                 "| method | {} families: ns/query (median) | FP rate (mean) | FN rate (mean) | "
                 "families with no error |\n|---|---|---|---|---|\n",
                 kind);
  for (const std::string& m : first_seen(rows, &SpeedAccuracyRow::method)) {
    std::vector<double> ns;
    double fp = 0, fn = 0;
    int clean = 0;
    for (const SpeedAccuracyRow& r : rows) {
      if (r.method != m) continue;
      ns.push_back(r.ns_per_query);
      fp += r.fp_rate;
      fn += r.fn_rate;
      clean += r.error_rate() == 0;
    }
    const double families = double(ns.size());
    std::nth_element(ns.begin(), ns.begin() + ns.size() / 2, ns.end());
    fmt::format_to(to, "| {} | {:.1f} | {:.3g} | {:.3g} | {} of {} |\n", m, ns[ns.size() / 2],
                   fp / families, fn / families, clean, ns.size());
  }
}

// For each sweep and method: the first parameter with failures, and the worst rate.
void stability_table(Out to, const std::vector<StabilityRow>& rows) {
  const std::vector<std::string> methods = first_seen(rows, &StabilityRow::method);
  fmt::format_to(to, "| sweep | {} |\n|---|", fmt::join(methods, " | "));
  for (std::size_t i = 0; i < methods.size(); ++i) fmt::format_to(to, "---|");
  fmt::format_to(to, "\n");
  for (const std::string& sweep : first_seen(rows, &StabilityRow::sweep)) {
    fmt::format_to(to, "| {} |", sweep);
    for (const std::string& m : methods) {
      int first = -1;
      double worst = 0;
      for (const StabilityRow& r : rows) {
        if (r.sweep != sweep || r.method != m) continue;
        if (r.failure_rate > 0 && first < 0) first = r.parameter;
        worst = std::max(worst, r.failure_rate);
      }
      if (first < 0)
        fmt::format_to(to, " never wrong |");
      else
        fmt::format_to(to, " wrong from p = {}, worst {:.3g} |", first, worst);
    }
    fmt::format_to(to, "\n");
  }
}

void kdop_table(Out to, const std::vector<KdopTreeRow>& rows) {
  fmt::format_to(to,
                 "| k | cloth grid | cloth / obstacle triangles | build ms | refit ms | "
                 "traverse ms | candidate pairs |\n|---|---|---|---|---|---|---|\n");
  for (const KdopTreeRow& r : rows)
    fmt::format_to(to, "| {} | {}×{} | {} / {} | {:.3g} | {:.3g} | {:.3g} | {} |\n", r.k, r.grid,
                   r.grid, r.cloth_triangles, r.obstacle_triangles, r.build_ms, r.refit_ms,
                   r.traverse_ms, r.candidate_pairs);
}

// One method's rows summed over the moving families: the counts added, the worst early time,
// and as its time the median over families of the time per query.
ToiSpeedRow toi_total(const std::vector<ToiSpeedRow>& rows, const std::string& name) {
  ToiSpeedRow sum{name, "all moving"};
  std::vector<double> ns;
  for (const ToiSpeedRow& r : rows) {
    if (r.method != name) continue;
    sum.queries += r.queries, sum.contacts += r.contacts, sum.late += r.late;
    sum.early += r.early, sum.zero += r.zero, sum.verdict_errors += r.verdict_errors;
    sum.early_max = std::max(sum.early_max, r.early_max);
    ns.push_back(r.ns_per_query);
  }
  if (ns.empty()) return sum;
  std::nth_element(ns.begin(), ns.begin() + ns.size() / 2, ns.end());
  sum.ns_per_query = ns[ns.size() / 2];
  return sum;
}

// One line per method; then float-cubic's late and early counts in words (issue 19).
void toi_speed_table(Out to, const std::vector<ToiSpeedRow>& rows) {
  fmt::format_to(
      to,
      "| method | TOIs | contacts | ns/query (median of families) | early max | late "
      "| early > 2^-30 | zero | verdict errors |\n|---|---|---|---|---|---|---|---|---|\n");
  const std::vector<std::string> methods = first_seen(rows, &ToiSpeedRow::method);
  for (const std::string& name : methods) {
    const ToiSpeedRow t = toi_total(rows, name);
    fmt::format_to(to, "| {} | {} | {} | {:.1f} | {:.3g} | {} | {} | {} | {} |\n", name, t.queries,
                   t.contacts, t.ns_per_query, t.early_max, t.late, t.early, t.zero,
                   t.verdict_errors);
  }
  if (std::find(methods.begin(), methods.end(), "float-cubic") == methods.end()) return;
  const ToiSpeedRow f = toi_total(rows, "float-cubic");
  fmt::format_to(to,
                 "\nfloat-cubic, the naive baseline: **{} late** TOIs and **{} early** by more "
                 "than 2^-30 of the step, of {} contacts; {} of its TOIs are 0 where t* > 0.\n",
                 f.late, f.early, f.contacts, f.zero);
}

void toi_speed_section(Out to, const Measurements& m) {
  fmt::format_to(to,
                 "\n### Time of impact against speed\n\nEvery method that gives a time of "
                 "impact, asked for an enclosure 2^-30 wide, on the same {} queries of each "
                 "moving family: how early its t_lo is (t* - t_lo in step units, median and "
                 "maximum over the contacts it found in time; 0 drawn at 1e-18) against ns per "
                 "query, colour for the method and shape for the family. A late TOI (t_lo > t*, "
                 "or a contact missed) lets the cloth pass through: those points are ringed in "
                 "red with their count.\n\n![time of impact against speed](toi_speed.svg)\n\n",
                 m.per_family);
  toi_speed_table(to, m.toi_speed);
}

// Per sweep and method: the late TOIs over the sweep, the first p with one, the worst early.
void toi_stability_section(Out to, const Measurements& m) {
  fmt::format_to(to,
                 "\n### Time of impact as a contact turns grazing\n\nThe times of impact on "
                 "the angle, edge and tangency sweeps above ({} queries per point): how early "
                 "(median solid, maximum dashed; 0 drawn at 1e-18) and how many late, as the "
                 "contact turns grazing.\n\n![time of impact, grazing](toi_stability.svg)\n\n"
                 "| sweep | method | late TOIs | first late at p | early max |\n"
                 "|---|---|---|---|---|\n",
                 m.per_point);
  for (const std::string& sweep : first_seen(m.toi_stability, &ToiStabilityRow::sweep))
    for (const std::string& name : first_seen(m.toi_stability, &ToiStabilityRow::method)) {
      long late = 0;
      int first = -1;
      double worst = 0;
      for (const ToiStabilityRow& r : m.toi_stability) {
        if (r.sweep != sweep || r.method != name) continue;
        late += r.late;
        if (r.late > 0 && first < 0) first = r.parameter;
        worst = std::max(worst, r.early_max);
      }
      fmt::format_to(to, "| {} | {} | {} | {} | {:.3g} |\n", sweep, name, late,
                     first < 0 ? "never" : std::to_string(first), worst);
    }
}

void measurement_sections(Out to, const Measurements& m) {
  fmt::format_to(to,
                 "## Speed against accuracy\n\nEvery method on {} queries of each generator "
                 "family (docs/methods.md), rates against the exact twin. One point per method "
                 "and family; the black steps are the Pareto front of time against error "
                 "rate. Top: the static families (every method); bottom: the moving ones "
                 "(vertex-face and edge-edge CCD, where the paper's readings and the linear "
                 "system do not apply).\n\n![speed against accuracy](speed_accuracy.svg)\n\n",
                 m.per_family);
  speed_table(to, m.speed, "static");
  fmt::format_to(to, "\n");
  speed_table(to, m.speed, "moving");
  toi_speed_section(to, m);
  fmt::format_to(
      to,
      "\n## Where methods break\n\nThe share of queries each method gets wrong (against the "
      "exact twin) as one parameter goes to its degenerate limit: the angle between the motion "
      "and the plane (2^-p), the distance from the crossing to an edge (2^-p, inside or "
      "outside), the distance from the origin (2^p), the triangle's height over its base "
      "(2^-p); and for moving queries (CCD), the depth of a tangential dip of a point through a "
      "tilting triangle (2^-p, or a miss by as much: a double root of the coplanarity cubic), "
      "and the distance of all four points from one plane while the point sweeps across an "
      "edge (2^-p: every coefficient of the cubic that small). {} queries per point. The paper's "
      "readings fail at a constant rate because they "
      "have no inside test; what matters is where a curve rises.\n\n![stability]"
      "(stability.svg)\n\n",
      m.per_point);
  stability_table(to, m.stability);
  toi_stability_section(to, m);
  fmt::format_to(to, "{}", min_distance_markdown(m));
  fmt::format_to(to,
                 "\n## FDH k\n\nA cloth grid draped over a triangulated sphere ({} triangles), "
                 "the cloth tree swept over one step, traversal with the early-out slab along "
                 "the fall. More directions cost more per box and cull more pairs.\n\n"
                 "![FDH k](kdop_k.svg)\n\n",
                 m.kdop.empty() ? 0 : m.kdop.front().obstacle_triangles);
  kdop_table(to, m.kdop);
}

}  // namespace

std::string certificate_section(const Certificate& c) {
  const std::string md = certificate_markdown(c);
  const std::size_t body = md.find("\n\n");  // after the title
  return body == std::string::npos ? md : md.substr(body + 2);
}

Report make_report(const CertifyOptions& options, const ProgressSink& progress) {
  const auto step = [&](const std::string& what) { report(progress, {what, 0, 0, ""}); };
  Report r;
  step("certificate");
  r.certificate = certify(options);
  Measurements& m = r.measurements;
  m.per_family = options.quick ? 100 : 1000;
  m.per_point = options.quick ? 100 : 400;
  step("speed against accuracy");
  m.speed = speed_accuracy(m.per_family, options.seed, progress);
  m.pareto = pareto_fronts(m.speed);
  step("stability sweeps");
  m.stability = stability(m.per_point, options.seed, progress);
  step("time of impact");
  m.toi_speed = toi_speed(m.per_family, options.seed, progress);
  m.toi_stability = toi_stability(m.per_point, options.seed, progress);
  step("minimum separation");  // few queries: the exact twin at δ > 0 costs more per query
  m.per_delta = options.quick ? 10 : 40;
  m.per_delta_point = options.quick ? 20 : 60;
  m.min_distance_speed = min_distance_speed(m.per_delta, options.seed, progress);
  m.min_distance_stability = min_distance_stability(m.per_delta_point, options.seed, progress);
  step("FDH k");
  for (const int grid : {30, 50, 100}) {
    const std::vector<KdopTreeRow> rows = kdop_tree(grid);
    m.kdop.insert(m.kdop.end(), rows.begin(), rows.end());
  }
  return r;
}

std::string report_markdown(const Report& report) {
  const Certificate& c = report.certificate;
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to,
                 "# fdhcert verification report\n\nWritten by `./run verify` (`fdhcert report "
                 "--out {}`) at commit `{}`{}. Every number here is measured by that run; times "
                 "vary between runs and machines, so compare rows within this report. Data: "
                 "`data/*.csv`.\n\n## At a glance\n\n{}\n## Certificate\n\n{}\n",
                 c.options.out_dir, c.commit, c.options.quick ? ", quick samples" : "",
                 glance_markdown(report), certificate_section(c));
  measurement_sections(to, report.measurements);
  return fmt::to_string(out);
}

std::vector<std::string> report_outputs() {
  return {"certificate.json",
          "certificate.md",
          "data/speed_accuracy.csv",
          "data/pareto.csv",
          "data/stability.csv",
          "data/toi_speed.csv",
          "data/toi_stability.csv",
          "data/kdop_tree.csv",
          "data/min_distance_speed.csv",
          "data/min_distance_stability.csv",
          "speed_accuracy.png",
          "speed_accuracy.svg",
          "stability.png",
          "stability.svg",
          "toi_speed.png",
          "toi_speed.svg",
          "toi_stability.png",
          "toi_stability.svg",
          "kdop_k.png",
          "kdop_k.svg",
          "min_distance_speed.png",
          "min_distance_speed.svg",
          "min_distance_stability.png",
          "min_distance_stability.svg",
          "report.md",
          "index.html"};
}

std::vector<std::string> report_owned() {
  std::vector<std::string> owned = report_outputs();
  for (std::string& o : certify_outputs()) owned.push_back(std::move(o));
  return owned;
}

void write_report(const Report& report) {
  const fs::path dir(report.certificate.options.files_dir());
  const Measurements& m = report.measurements;
  check_output_dir(dir.string(), report_outputs());
  fs::create_directories(dir / "data");
  write_certificate(report.certificate);
  write_file_atomically((dir / "data/speed_accuracy.csv").string(), speed_accuracy_csv(m.speed));
  write_file_atomically((dir / "data/pareto.csv").string(), pareto_csv(m.pareto));
  write_file_atomically((dir / "data/stability.csv").string(), stability_csv(m.stability));
  write_file_atomically((dir / "data/toi_speed.csv").string(), toi_speed_csv(m.toi_speed));
  write_file_atomically((dir / "data/toi_stability.csv").string(),
                        toi_stability_csv(m.toi_stability));
  write_file_atomically((dir / "data/kdop_tree.csv").string(), kdop_tree_csv(m.kdop));
  write_file_atomically((dir / "data/min_distance_speed.csv").string(),
                        min_distance_speed_csv(m.min_distance_speed));
  write_file_atomically((dir / "data/min_distance_stability.csv").string(),
                        min_distance_stability_csv(m.min_distance_stability));
  draw_report_charts(dir.string(), m);
  draw_min_distance_charts(dir.string(), m);
  write_file_atomically((dir / "report.md").string(), report_markdown(report));
  write_file_atomically((dir / "index.html").string(), report_html(report, dir.string()));
}

}  // namespace fdh::verify
