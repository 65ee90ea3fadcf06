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

// The three panels of one kind of family (static or moving): FN rate, FP rate, and the error
// rate with that kind's Pareto front.
std::string speed_panels(const Measurements& m, const std::string& kind) {
  std::vector<SpeedAccuracyRow> rows;
  for (const SpeedAccuracyRow& r : m.speed)
    if (r.kind == kind) rows.push_back(r);
  if (rows.empty()) return "";
  const std::vector<std::string> methods = drawing_order(rows);
  const std::string of_kind = fmt::format("strcol(7) eq {} && strcol(1)", gnuplot_quote(kind));
  const auto panel = [&](const std::string& y) {
    return per_method("data/speed_accuracy.csv", methods, of_kind, "$4", y, "points pt 7 ps 1.2",
                      drawing_order(m.speed));
  };
  return fmt::format(
      "set key inside center right box opaque\n"
      "set ylabel '{0} families: false-negative rate'\nplot {1}\nunset key\n"
      "set ylabel '{0} families: false-positive rate'\nplot {2}\n"
      "set key inside center right box opaque\n"
      "set ylabel '{0}: error rate (FP + FN), Pareto front'\nplot {3}, \\\n"
      "     {4} skip 1 using (strcol(5) eq {5} ? $3 : NaN):4 with steps lw 2 lc rgb 'black' "
      "title 'Pareto front'\n",
      kind, panel("6"), panel("5"), panel("($5+$6)"), gnuplot_quote("data/pareto.csv"),
      gnuplot_quote(kind));
}

Chart speed_chart(const fs::path& dir, const Measurements& m) {
  return {(dir / "speed_accuracy").string(), 1500, 1000,
          fmt::format("set multiplot layout 2,3 title \"Speed against accuracy: one point per "
                      "method and generator family (fdhcert report)\"\n"
                      "set logscale x\nset xlabel 'ns per query (log)'\nset yrange [-0.02:1.02]\n"
                      "{}{}unset multiplot",
                      speed_panels(m, "static"), speed_panels(m, "moving"))};
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
                      "set yrange [1e-4:1.5]\nset ylabel 'failure rate'\nset key inside left top\n"
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
                      "set key inside left top\nset offsets graph 0.05, graph 0.1, 0, 0\n"
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
