#include "speed_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "markdown_html.hpp"

namespace fdh::verify {
namespace {

// gnuplot's default colours of line types 1..8, so that a method looks as in the PNG chart.
const char* const kColours[] = {"#9400d3", "#009e73", "#56b4e9", "#e69f00",
                                "#f0e442", "#0072b2", "#e51e10", "#000000"};

constexpr double kWidth = 960, kHeight = 340;  // one panel with its key
constexpr double kLeft = 70, kRight = 760, kTop = 30, kBottom = 290;

// The methods in the gnuplot chart's order (report_charts.cpp: reverse of first appearance), so
// that method i has colour i there and here.
std::vector<std::string> speed_palette(const std::vector<SpeedAccuracyRow>& rows) {
  std::vector<std::string> out;
  for (const SpeedAccuracyRow& r : rows)
    if (std::find(out.begin(), out.end(), r.method) == out.end()) out.push_back(r.method);
  std::reverse(out.begin(), out.end());
  return out;
}

const char* method_colour(const std::vector<std::string>& p, const std::string& method) {
  const std::size_t i = std::size_t(std::find(p.begin(), p.end(), method) - p.begin());
  return kColours[i % std::size(kColours)];
}

// Whole decades around the times of `rows`.
std::pair<double, double> decades(const std::vector<SpeedAccuracyRow>& rows) {
  double lo = 1e300, hi = 0;
  for (const SpeedAccuracyRow& r : rows)
    if (r.ns_per_query > 0) lo = std::min(lo, r.ns_per_query), hi = std::max(hi, r.ns_per_query);
  if (hi <= 0) return {0, 1};
  return {std::floor(std::log10(lo)),
          std::max(std::ceil(std::log10(hi)), std::floor(std::log10(lo)) + 1)};
}

std::string axes(double lo, double hi, const std::string& kind) {
  std::string out = fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", kLeft,
      kTop, kRight - kLeft, kBottom - kTop);
  for (double d = lo; d <= hi; ++d) {
    const double x = kLeft + (d - lo) / (hi - lo) * (kRight - kLeft);
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/><text "
        "x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4:g}</text>\n",
        x, kTop, kBottom, kBottom + 18, std::pow(10.0, d));
  }
  for (int i = 0; i <= 5; ++i) {
    const double y = kBottom - i / 5.0 * (kBottom - kTop);
    out += fmt::format(
        "<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#ddd\"/><text "
        "x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:g}</text>\n",
        kLeft, y, kRight, kLeft - 6, y + 4, i / 5.0);
  }
  return out + fmt::format(
                   "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">ns per query (log)</text>\n"
                   "<text transform=\"translate(18,{}) rotate(-90)\" text-anchor=\"middle\">{}: "
                   "FP + FN rate</text>\n",
                   (kLeft + kRight) / 2, kBottom + 40, (kTop + kBottom) / 2, kind);
}

std::string point(const SpeedAccuracyRow& r, double x, double y, const char* fill) {
  const std::string title = fmt::format(
      "{} on {} ({}): FP rate {:.3g}, FN rate {:.3g} of {} queries; {:.1f} ns per query", r.method,
      r.family, r.kind, r.fp_rate, r.fn_rate, r.queries, r.ns_per_query);
  return fmt::format(
      "<circle class=\"point\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"5\" fill=\"{}\" "
      "stroke=\"#222\" stroke-width=\"0.5\" data-method=\"{}\" data-family=\"{}\" "
      "data-fp=\"{:.4g}\" data-fn=\"{:.4g}\" data-ns=\"{:.1f}\"><title>{}</title></circle>\n",
      x, y, fill, html_escape(r.method), html_escape(r.family), r.fp_rate, r.fn_rate,
      r.ns_per_query, html_escape(title));
}

std::string panel(const std::vector<SpeedAccuracyRow>& all, const std::string& kind) {
  std::vector<SpeedAccuracyRow> rows;
  for (const SpeedAccuracyRow& r : all)
    if (r.kind == kind) rows.push_back(r);
  if (rows.empty()) return "";
  const std::vector<std::string> methods = speed_palette(all);
  const auto [lo, hi] = decades(rows);
  std::string out = fmt::format(
      "<svg class=\"chart\" viewBox=\"0 0 {} {}\" role=\"img\" font-family=\"sans-serif\" "
      "font-size=\"12\"><title>speed against accuracy, {} families</title>\n{}",
      kWidth, kHeight, kind, axes(lo, hi, kind));
  for (const std::string& m : methods)  // the twin and the exact methods last, on top
    for (const SpeedAccuracyRow& r : rows) {
      if (r.method != m || r.ns_per_query <= 0) continue;
      const double x = kLeft + (std::log10(r.ns_per_query) - lo) / (hi - lo) * (kRight - kLeft);
      const double y = kBottom - std::min(r.error_rate(), 1.0) * (kBottom - kTop);
      out += point(r, x, y, method_colour(methods, m));
    }
  double key_y = kTop + 10;
  for (auto m = methods.rbegin(); m != methods.rend(); ++m, key_y += 20)
    out += fmt::format(
        "<circle cx=\"{0}\" cy=\"{1}\" r=\"5\" fill=\"{2}\"/><text x=\"{3}\" "
        "y=\"{4}\">{5}</text>\n",
        kRight + 25, key_y, method_colour(methods, *m), kRight + 37, key_y + 4, html_escape(*m));
  return out + "</svg>\n";
}

}  // namespace

std::string speed_accuracy_svg(const std::vector<SpeedAccuracyRow>& rows) {
  return panel(rows, "static") + panel(rows, "moving");
}

}  // namespace fdh::verify
