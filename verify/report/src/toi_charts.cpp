// The report's two time-of-impact charts, from data/toi_speed.csv and data/toi_stability.csv:
// how early each method's TOI is against its speed (colour = method, point shape = family),
// and how early and how often late as a contact turns grazing. Errors of 0 are drawn at a floor
// the titles name; late TOIs are ringed and counted. Keys sit outside the panels.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "fdh/io/charts.hpp"
#include "fdh/report/report_document.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// An early time of 0 (exact, or a t_lo that is t* to the last bit) is drawn here: below the
// 2^-53 that a t* rounded to a double resolves.
constexpr const char* kEarlyFloor = "1e-18";

template <class Row, class Field>
std::vector<std::string> distinct(const std::vector<Row>& rows, Field Row::*field) {
  std::vector<std::string> out;
  for (const Row& r : rows)
    if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
  return out;
}

// The methods of both charts, each with its colour (gnuplot line type: place + 1) in both.
std::vector<std::string> toi_palette(const Measurements& m) {
  std::vector<std::string> out = distinct(m.toi_speed, &ToiSpeedRow::method);
  for (const std::string& name : distinct(m.toi_stability, &ToiStabilityRow::method))
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  return out;
}

std::size_t colour(const std::vector<std::string>& palette, const std::string& name) {
  return std::size_t(std::find(palette.begin(), palette.end(), name) - palette.begin()) + 1;
}

// A family's point shape: filled shapes first, then open ones (6, the open circle, rings late
// points).
int family_shape(std::size_t i) {
  static const int shapes[] = {5, 7, 9, 11, 13, 4, 8, 10, 12, 14, 1, 2, 3};
  return shapes[i % std::size(shapes)];
}

std::string floored(const std::string& column) {
  return fmt::format("(${0} > {1} ? ${0} : {1})", column, kEarlyFloor);
}

// One panel of toi_speed.csv: x = ns per query (column 5), y = `y` (a gnuplot expression); a
// point per method and family, with `extra` clauses drawn over them. With `key`, the key's
// entries (no data of their own), placed by the caller outside the panels.
std::string toi_speed_panel(const Measurements& m, const std::string& y, const std::string& extra,
                            bool key) {
  const std::vector<std::string> methods = distinct(m.toi_speed, &ToiSpeedRow::method);
  const std::vector<std::string> families = distinct(m.toi_speed, &ToiSpeedRow::family);
  std::vector<std::string> plots;
  for (std::size_t i = 0; i < methods.size(); ++i)
    for (std::size_t f = 0; f < families.size(); ++f)
      plots.push_back(fmt::format(
          "{} skip 1 using (strcol(1) eq {} && strcol(2) eq {} ? $5 : NaN):{} with points pt {} "
          "ps 1.6 lt {} notitle",
          plots.empty() ? gnuplot_quote("data/toi_speed.csv") : "''", gnuplot_quote(methods[i]),
          gnuplot_quote(families[f]), y, family_shape(f), i + 1));
  if (!extra.empty()) plots.push_back(extra);
  if (key) {
    for (std::size_t i = 0; i < methods.size(); ++i)
      plots.push_back(fmt::format("NaN with points pt 7 ps 1.6 lt {} title {}", i + 1,
                                  gnuplot_quote(methods[i])));
    for (std::size_t f = 0; f < families.size(); ++f)
      plots.push_back(fmt::format("NaN with points pt {} ps 1.6 lc rgb 'black' title {}",
                                  family_shape(f), gnuplot_quote(families[f])));
    plots.push_back("NaN with points pt 6 ps 3 lw 2 lc rgb 'red' title 'has late TOIs'");
  }
  return fmt::format("plot {}\n", fmt::join(plots, ", \\\n     "));
}

// The early panels' red rings round the points of a method and family with late TOIs.
std::string late_rings(const std::string& y) {
  return fmt::format(
      "'' skip 1 using ($8 > 0 ? $5 : NaN):{} with points pt 6 ps 3.5 lw 2 lc rgb 'red' notitle",
      y);
}

// Panels side by side at fixed places, leaving the right edge to the key.
std::string at_panel(int i) {
  return fmt::format("set lmargin at screen {:.3f}\nset rmargin at screen {:.3f}\n",
                     0.045 + 0.29 * i, 0.265 + 0.29 * i);
}

Chart toi_speed_chart(const fs::path& dir, const Measurements& m) {
  const std::string median = floored("6"), max = floored("7");
  return {(dir / "toi_speed").string(), 1800, 650,
          fmt::format(
              "set multiplot title \"Time of impact against speed: one point per method (colour) "
              "and moving family (shape), {0} queries each; early = t* - t_lo in step units, 0 "
              "drawn at {1}\"\n"
              "set tmargin at screen 0.9\nset bmargin at screen 0.12\n"
              "set logscale x\nset xlabel 'ns per query (log)'\nset offsets graph 0.05, graph "
              "0.05, 0, 0\nset key at screen 0.995, screen 0.9 right top box\n"
              "set logscale y\nset format y '%.0e'\nset yrange [{1}/10:2]\n"
              "set arrow 1 from graph 0, first {2} to graph 1, first {2} nohead dt 2\n"
              "set label 1 'width asked 2^{{-30}}' at graph 0.02, first {2} offset 0,0.6\n"
              "{3}set ylabel 'median early (log)'\n{4}{5}set ylabel 'maximum early (log)'\n{6}"
              "unset arrow 1\nunset label 1\nunset logscale y\nset format y '%g'\n"
              "set yrange [-{0}/20.0:*]\n{7}set ylabel 'late TOIs (t_lo > t*, or contact missed)'\n"
              "{8}unset multiplot",
              m.per_family, kEarlyFloor, kToiWidthAsked, at_panel(0),
              toi_speed_panel(m, median, late_rings(median), false), at_panel(1),
              toi_speed_panel(m, max, late_rings(max), false), at_panel(2),
              toi_speed_panel(m, "8", "", true))};
}

// One sweep's two panels: early (median solid, maximum dashed) and the late count, against p.
std::string toi_sweep_panels(const Measurements& m, const StabilitySweep& sw) {
  const std::vector<std::string> methods = distinct(m.toi_stability, &ToiStabilityRow::method);
  const std::vector<std::string> palette = toi_palette(m);
  const std::string of_sweep =
      fmt::format("strcol(1) eq {} && strcol(3) eq ", gnuplot_quote(sw.name));
  std::vector<std::string> early, late;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string is = of_sweep + gnuplot_quote(methods[i]);
    early.push_back(fmt::format(
        "{} skip 1 using ({} ? $2 : NaN):{} with linespoints pt 7 ps 0.6 lw 2 lt {} title {}, "
        "'' skip 1 using ({} ? $2 : NaN):{} with lines dt 2 lw 1.5 lt {} notitle",
        early.empty() ? gnuplot_quote("data/toi_stability.csv") : "''", is, floored("7"),
        colour(palette, methods[i]), gnuplot_quote(methods[i] + " median (max dashed)"), is,
        floored("8"), colour(palette, methods[i])));
    late.push_back(fmt::format(
        "{} skip 1 using ({} ? $2 : NaN):6 with linespoints pt 7 ps 0.6 lw 2 lt {} title {}",
        late.empty() ? gnuplot_quote("data/toi_stability.csv") : "''", is,
        colour(palette, methods[i]), gnuplot_quote(methods[i])));
  }
  return fmt::format(
      "set logscale y\nset format y '%.0e'\nset yrange [{}/10:2]\nset xlabel {}\n"
      "set ylabel 'early: t* - t_lo (log)'\nplot {}\n"
      "unset logscale y\nset format y '%g'\nset yrange [-0.5:*]\n"
      "set ylabel 'late TOIs (of {} queries)'\nplot {}\n",
      kEarlyFloor, gnuplot_quote(sw.axis), fmt::join(early, ", \\\n     "), m.per_point,
      fmt::join(late, ", \\\n     "));
}

Chart toi_stability_chart(const fs::path& dir, const Measurements& m) {
  std::string panels;
  int sweeps = 0;
  for (const StabilitySweep& sw : toi_stability_sweeps())
    if (std::any_of(m.toi_stability.begin(), m.toi_stability.end(),
                    [&](const ToiStabilityRow& r) { return r.sweep == sw.name; })) {
      panels += toi_sweep_panels(m, sw);
      ++sweeps;
    }
  return {(dir / "toi_stability").string(), 1500, 500 * std::max(sweeps, 1),
          fmt::format("set multiplot layout {},2 title \"Time of impact as a contact turns "
                      "grazing: how early (0 drawn at {}) and how often late, per method\"\n"
                      "set key outside bottom center horizontal\n{}unset multiplot",
                      std::max(sweeps, 1), kEarlyFloor, panels)};
}

}  // namespace

void draw_toi_charts(const std::string& dir, const Measurements& m) {
  const fs::path d(dir);
  draw_chart(toi_speed_chart(d, m));
  draw_chart(toi_stability_chart(d, m));
}

}  // namespace fdh::verify
