// The report's minimum-separation charts and section (issue 30), from
// data/min_distance_speed.csv and data/min_distance_stability.csv: speed against accuracy per
// method at each δ (colour = method, shape = δ), and the failure rate of each method as the
// true least distance approaches D from below and from above.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iterator>

#include "fdh/io/charts.hpp"
#include "fdh/report/report_document.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

template <class Row, class Field>
std::vector<std::string> delta_distinct(const std::vector<Row>& rows, Field Row::*field) {
  std::vector<std::string> out;
  for (const Row& r : rows)
    if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
  return out;
}

std::size_t delta_colour(const std::vector<std::string>& palette, const std::string& name) {
  return std::size_t(std::find(palette.begin(), palette.end(), name) - palette.begin()) + 1;
}

std::string delta_label(int exponent) {
  return exponent == 0 ? "0" : fmt::format("2^-{}", exponent);
}

// One panel of one kind: a point per method and δ at (ns per query, FP + FN rate).
std::string delta_speed_panel(const Measurements& m, const std::string& kind) {
  const std::vector<std::string> palette =
      delta_distinct(m.min_distance_speed, &MinDistanceSpeedRow::method);
  static const int shapes[] = {7, 5, 9, 11};
  std::vector<std::string> plots;
  for (const std::string& name : palette)
    for (std::size_t d = 0; d < min_distance_exponents().size(); ++d)
      plots.push_back(fmt::format(
          "{} skip 1 using (strcol(3) eq {} && strcol(1) eq {} && strcol(2) eq {} ? $5 : NaN):"
          "($6+$7) with points pt {} ps 1.8 lt {} {}",
          plots.empty() ? gnuplot_quote("data/min_distance_speed.csv") : "''", gnuplot_quote(kind),
          gnuplot_quote(name), gnuplot_quote(delta_label(min_distance_exponents()[d])), shapes[d],
          delta_colour(palette, name), d == 0 ? "title " + gnuplot_quote(name) : "notitle"));
  for (std::size_t d = 0; d < min_distance_exponents().size(); ++d)
    plots.push_back(fmt::format("NaN with points pt {} ps 1.8 lc rgb 'black' title {}", shapes[d],
                                gnuplot_quote("δ = " + delta_label(min_distance_exponents()[d]) +
                                              (d == 0 ? "" : " × size"))));
  return fmt::format("set title '{} families'\nplot {}\n", kind, fmt::join(plots, ", \\\n     "));
}

Chart delta_speed_chart(const fs::path& dir, const Measurements& m) {
  return {
      (dir / "min_distance_speed").string(), 1300, 1000,
      fmt::format("set multiplot layout 2,1 title \"Minimum separation: speed against "
                  "accuracy at δ = 0, 2^-40, 2^-20, 2^-10 times each query's size, {} "
                  "queries per family (fdhcert report)\"\nset logscale x\n"
                  "set xlabel 'ns per query (log)'\nset ylabel 'error rate (FP + FN) vs the "
                  "exact twin at δ'\nset yrange [-0.02:1.02]\nset key outside right top vertical\n"
                  "{}{}unset multiplot",
                  m.per_delta, delta_speed_panel(m, "static"), delta_speed_panel(m, "moving"))};
}

Chart delta_stability_chart(const fs::path& dir, const Measurements& m) {
  const std::vector<std::string> methods =
      delta_distinct(m.min_distance_stability, &MinDistanceStabilityRow::method);
  std::vector<std::string> plots, tics;
  for (const std::string& name : methods)
    plots.push_back(fmt::format(
        "{} skip 1 using (strcol(4) eq {} ? $3 : NaN):($6 > 1e-4 ? $6 : 1e-4) with linespoints "
        "lw 2 lt {} title {}",
        plots.empty() ? gnuplot_quote("data/min_distance_stability.csv") : "''",
        gnuplot_quote(name), delta_colour(methods, name), gnuplot_quote(name)));
  if (plots.empty())  // no method answers δ > 0 (a build whose twin does not yet)
    plots.push_back("NaN title 'no method answers δ > 0'");
  tics.push_back("'D' 0");
  for (const int p : min_distance_stability_steps())
    tics.push_back(fmt::format("'-2^-{0}' {1}, '+2^-{0}' {2}", p, -(60 - p), 60 - p));
  return {(dir / "min_distance_stability").string(), 1300, 650,
          fmt::format("set title \"Minimum separation: answers wrong at δ = D = 2^-20 as the least "
                      "distance D·(1 + s) nears D (within iff s <= 0)\\n{} queries per point; 0 "
                      "drawn at 1e-4\"\nset logscale y\n"
                      "set yrange [1e-4:1.5]\nset ylabel 'failure rate'\n"
                      "set xlabel 's (below D: left; above D: right)'\nset xtics ({}) rotate "
                      "by -45\nset key below horizontal\nplot {}\n",
                      m.per_delta_point, fmt::join(tics, ", "), fmt::join(plots, ", \\\n     "))};
}

// Per kind and method: FP and FN rates and ns per query at each δ.
void delta_speed_table(std::back_insert_iterator<fmt::memory_buffer> to, const Measurements& m) {
  fmt::format_to(to, "| kind | method |");
  for (const int e : min_distance_exponents()) fmt::format_to(to, " δ = {} |", delta_label(e));
  fmt::format_to(to, "\n|---|---|{}\n", fmt::join(std::vector<std::string>(4, "---|"), ""));
  for (const std::string kind : {"static", "moving"})
    for (const std::string& name :
         delta_distinct(m.min_distance_speed, &MinDistanceSpeedRow::method)) {
      std::string cells;
      for (const int e : min_distance_exponents()) {
        std::string cell = "n/a";
        for (const MinDistanceSpeedRow& r : m.min_distance_speed)
          if (r.kind == kind && r.method == name && r.exponent == e)
            cell = fmt::format("{:.1f} ns, FP {:.3g}, FN {:.3g}", r.ns_per_query, r.fp_rate,
                               r.fn_rate);
        cells += " " + cell + " |";
      }
      fmt::format_to(to, "| {} | {} |{}\n", kind, name, cells);
    }
}

// Per method: its wrong answers below D and above D over the whole sweep.
void delta_stability_table(std::back_insert_iterator<fmt::memory_buffer> to,
                           const Measurements& m) {
  fmt::format_to(to,
                 "\n| method | misses (H <= D, said no) | false alarms (H > D, said yes) | "
                 "first wrong at |\n|---|---|---|---|\n");
  for (const std::string& name :
       delta_distinct(m.min_distance_stability, &MinDistanceStabilityRow::method)) {
    double misses = 0, alarms = 0;
    std::string first = "never";
    for (const MinDistanceStabilityRow& r : m.min_distance_stability) {
      if (r.method != name) continue;
      const double wrong = r.failure_rate * double(r.queries);
      (r.side <= 0 ? misses : alarms) += wrong;
      if (wrong > 0 && first == "never")
        first = r.side == 0 ? "s = 0" : fmt::format("s = {}2^-{}", r.side < 0 ? "-" : "+", r.p);
    }
    fmt::format_to(to, "| {} | {:.0f} | {:.0f} | {} |\n", name, misses, alarms, first);
  }
}

}  // namespace

void draw_min_distance_charts(const std::string& dir, const Measurements& m) {
  const fs::path d(dir);
  draw_chart(delta_speed_chart(d, m));
  draw_chart(delta_stability_chart(d, m));
}

std::string min_distance_markdown(const Measurements& m) {
  if (m.min_distance_speed.empty() && m.min_distance_stability.empty()) return "";  // not measured
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(
      to,
      "\n## Minimum separation\n\nThe question of issue 30 (docs/methods.md, \"Minimum "
      "separation\"): do the closed primitives come within Euclidean distance δ at some time "
      "of the step. Every method that answers it, on {} queries of each generator family at "
      "δ = 0 and δ = 2^-40, 2^-20 and 2^-10 times each query's own size (its largest extent "
      "along an axis, rounded down to a power of two), rates against the exact twin at that δ; "
      "a method that answers contact only has no point at δ > 0.\n\n"
      "![minimum separation: speed against accuracy](min_distance_speed.svg)\n\n",
      m.per_delta);
  delta_speed_table(to, m);
  fmt::format_to(
      to,
      "\n### As the least distance approaches δ\n\nQueries whose least distance is exactly H = "
      "D·(1 + s), by construction (a point over a face, beside an edge, beyond a corner; "
      "parallel and crossing edges; axes permuted), asked at δ = D = 2^-20, for s = ±2^-p, p = "
      "10 to 50, and s = 0: within iff s <= 0. {} queries per point; the twin's line is the "
      "construction checked.\n\n![minimum separation: stability](min_distance_stability.svg)\n",
      m.per_delta_point);
  delta_stability_table(to, m);
  return fmt::to_string(out);
}

}  // namespace fdh::verify
