// The report's verdict and k-DOP charts (the TOI charts: toi_charts.cpp), their plot commands
// built from the measurements' rows: one curve or point set per method and sweep found in the
// rows, read from the data files. Static and moving families get a row of panels each.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "fdh/io/charts.hpp"
#include "fdh/report/report_document.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// Methods in the reverse of the registry's order, so that the twin and the methods that
// promise to equal it (first in the registry, at 0 error) are drawn last, on top.
template <class Row>
std::vector<std::string> drawing_order(const std::vector<Row>& rows) {
  std::vector<std::string> out;
  for (const Row& r : rows)
    if (std::find(out.begin(), out.end(), r.method) == out.end()) out.push_back(r.method);
  std::reverse(out.begin(), out.end());
  return out;
}

// gnuplot's line type of a method: its place in `palette` (every method of the chart), so that
// a method keeps its colour from panel to panel.
int line_type(const std::vector<std::string>& palette, const std::string& m) {
  return int(std::find(palette.begin(), palette.end(), m) - palette.begin()) + 1;
}

// One plot clause per method: the rows of `data` where `filter` (a gnuplot string
// expression) equals the method's name, at (x, y).
std::string per_method(const std::string& data, const std::vector<std::string>& methods,
                       const std::string& filter, const std::string& x, const std::string& y,
                       const std::string& style, const std::vector<std::string>& palette) {
  std::vector<std::string> plots;
  for (const std::string& m : methods)
    plots.push_back(fmt::format("{} skip 1 using ({} eq {} ? {} : NaN):{} with {} lt {} title {}",
                                plots.empty() ? gnuplot_quote(data) : "''", filter,
                                gnuplot_quote(m), x, y, style, line_type(palette, m),
                                gnuplot_quote(m)));
  return fmt::format("{}", fmt::join(plots, ", \\\n     "));
}

// A family's point shape (gnuplot point type) within its kind: 15 distinct shapes, filled and
// open, enough for every static family.
int speed_shape(std::size_t family) {
  static const int shapes[] = {7, 5, 9, 11, 13, 6, 4, 8, 10, 12, 1, 2, 3, 14, 15};
  return shapes[family % std::size(shapes)];
}

// Panels side by side at fixed places, one row per kind, the right edge left to the key.
std::string speed_panel_at(int column, int row) {
  return fmt::format(
      "set lmargin at screen {:.3f}\nset rmargin at screen {:.3f}\n"
      "set tmargin at screen {:.3f}\nset bmargin at screen {:.3f}\n",
      0.06 + 0.255 * column, 0.25 + 0.255 * column, 0.93 - 0.47 * row, 0.55 - 0.47 * row);
}

// One panel of one kind of family: a point per method (colour, as in every panel) and family
// (shape) at (ns per query, `y`), with `extra` clauses over them; with `key`, the key's entries
// (no data of their own), which sit right of the panels.
std::string speed_panel(const Measurements& m, const std::string& kind, const std::string& y,
                        const std::string& extra, bool key) {
  std::vector<SpeedAccuracyRow> rows;
  for (const SpeedAccuracyRow& r : m.speed)
    if (r.kind == kind) rows.push_back(r);
  const std::vector<std::string> palette = drawing_order(m.speed), methods = drawing_order(rows);
  std::vector<std::string> families;
  for (const SpeedAccuracyRow& r : rows)
    if (std::find(families.begin(), families.end(), r.family) == families.end())
      families.push_back(r.family);
  std::vector<std::string> plots;
  for (const std::string& name : methods)
    for (std::size_t f = 0; f < families.size(); ++f)
      plots.push_back(fmt::format(
          "{} skip 1 using (strcol(7) eq {} && strcol(1) eq {} && strcol(2) eq {} ? $4 : NaN):{} "
          "with points pt {} ps 1.5 lt {} notitle",
          plots.empty() ? gnuplot_quote("data/speed_accuracy.csv") : "''", gnuplot_quote(kind),
          gnuplot_quote(name), gnuplot_quote(families[f]), y, speed_shape(f),
          line_type(palette, name)));
  if (!extra.empty()) plots.push_back(extra);
  if (key) {
    for (auto name = methods.rbegin(); name != methods.rend(); ++name)
      plots.push_back(fmt::format("NaN with points pt 7 ps 1.5 lt {} title {}",
                                  line_type(palette, *name), gnuplot_quote(*name)));
    for (std::size_t f = 0; f < families.size(); ++f)
      plots.push_back(fmt::format("NaN with points pt {} ps 1.5 lc rgb 'black' title {}",
                                  speed_shape(f), gnuplot_quote(families[f])));
  }
  return fmt::format("plot {}\n", fmt::join(plots, ", \\\n     "));
}

// The three panels of one kind of family (static or moving): FN rate, FP rate, and the error
// rate with that kind's Pareto front; the key (methods, then families) right of them.
std::string speed_panels(const Measurements& m, const std::string& kind, int row) {
  if (std::none_of(m.speed.begin(), m.speed.end(),
                   [&](const SpeedAccuracyRow& r) { return r.kind == kind; }))
    return "";
  const std::string front = fmt::format(
      "{} skip 1 using (strcol(5) eq {} ? $3 : NaN):4 with steps lw 2 lc rgb 'black' title "
      "'Pareto front'",
      gnuplot_quote("data/pareto.csv"), gnuplot_quote(kind));
  return fmt::format(
      "set key at screen 0.995, screen {4:.3f} right top box spacing 0.9\n"
      "{5}set ylabel '{0} families: false-negative rate'\n{1}"
      "{6}set ylabel '{0} families: false-positive rate'\n{2}"
      "{7}set ylabel '{0}: error rate (FP + FN)'\n{3}",
      kind, speed_panel(m, kind, "6", "", false), speed_panel(m, kind, "5", "", false),
      speed_panel(m, kind, "($5+$6)", front, true), 0.93 - 0.47 * row, speed_panel_at(0, row),
      speed_panel_at(1, row), speed_panel_at(2, row));
}

Chart speed_chart(const fs::path& dir, const Measurements& m) {
  return {(dir / "speed_accuracy").string(), 1800, 1150,
          fmt::format("set multiplot title \"Speed against accuracy: one point per method "
                      "(colour) and generator family (shape), {} queries each; top: static "
                      "families, bottom: moving (fdhcert report)\"\n"
                      "set logscale x\nset xlabel 'ns per query (log)'\nset yrange [-0.02:1.02]\n"
                      "{}{}unset multiplot",
                      m.per_family, speed_panels(m, "static", 0), speed_panels(m, "moving", 1))};
}

Chart stability_chart(const fs::path& dir, const Measurements& m) {
  const std::string data = "data/stability.csv";
  const std::vector<std::string> methods = drawing_order(m.stability);
  std::set<std::string> measured;
  for (const StabilityRow& r : m.stability) measured.insert(r.sweep);
  std::string panels;
  for (const StabilitySweep& sw : stability_sweeps()) {
    if (!measured.count(sw.name)) continue;
    std::vector<std::string> of_sweep;  // the methods measured in this sweep
    for (const std::string& name : methods)
      if (std::any_of(m.stability.begin(), m.stability.end(), [&](const StabilityRow& r) {
            return r.sweep == sw.name && r.method == name;
          }))
        of_sweep.push_back(name);
    const std::string filter = fmt::format("strcol(1) eq {} && strcol(3)", gnuplot_quote(sw.name));
    const std::string plot = per_method(data, of_sweep, filter, "$2", "($4 > 1e-4 ? $4 : 1e-4)",
                                        "linespoints lw 2", methods);
    panels += fmt::format("set xlabel {}\nplot {}\n", gnuplot_quote(sw.axis), plot);
  }
  return {(dir / "stability").string(), 1300, 1300,
          fmt::format("set multiplot layout 3,2 title \"Where methods break: share of queries "
                      "wrong vs the exact twin (0 drawn at 1e-4)\"\nset logscale y\n"
                      "set yrange [1e-4:1.5]\nset ylabel 'failure rate'\nset key below horizontal\n"
                      "{}unset multiplot",
                      panels)};
}

Chart kdop_chart(const fs::path& dir, const Measurements& m) {
  std::vector<std::string> grids, ks;
  for (const KdopTreeRow& r : m.kdop) {
    const std::string g = fmt::format("{}×{}", r.grid, r.grid), k = std::to_string(r.k);
    if (std::find(grids.begin(), grids.end(), g) == grids.end()) grids.push_back(g);
    if (std::find(ks.begin(), ks.end(), k) == ks.end()) ks.push_back(k);
  }
  return {(dir / "kdop_k").string(), 900, 600,
          fmt::format("set title \"FDH tree, cloth over a sphere: time against candidate pairs "
                      "for k = {}\\n(one group per cloth size: {} particles; labels give k)\"\n"
                      "set xlabel 'candidate pairs (leaf pairs reported by traversal)'\n"
                      "set ylabel 'ms (median of 20, log)'\nset logscale y\n"
                      "set key outside right top\nset offsets graph 0.05, graph 0.1, 0, 0\n"
                      "plot {} skip 1 using 8:5 with linespoints pt 7 title 'build (swept)', \\\n"
                      "     '' skip 1 using 8:6 with linespoints pt 7 title 'refit', \\\n"
                      "     '' skip 1 using 8:7 with linespoints pt 7 title 'traverse', \\\n"
                      "     '' skip 1 using 8:5:(sprintf('%d', $1)) with labels offset 0,1 "
                      "notitle",
                      fmt::join(ks, ", "), fmt::join(grids, ", "),
                      gnuplot_quote("data/kdop_tree.csv"))};
}

}  // namespace

void draw_report_charts(const std::string& dir, const Measurements& m) {
  const fs::path d(dir);
  draw_chart(speed_chart(d, m));
  draw_chart(stability_chart(d, m));
  draw_toi_charts(dir, m);
  draw_chart(kdop_chart(d, m));
}

}  // namespace fdh::verify
