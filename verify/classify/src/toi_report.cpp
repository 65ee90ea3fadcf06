#include "fdh/classify/toi_report.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;

void print_block(std::ostream& os, const std::string& title, const ToiClassification& c) {
  os << fmt::format(
      "{}: time of impact at width {:g}, against the exact earliest contact t* "
      "(early = t* - t_lo, step units)\n",
      title, c.width);
  os << fmt::format("  {:<16} {:<16} {:>7} {:>7} {:>6} {:>7} {:>6} {:>10} {:>10} {:>10}\n",
                    "method", "promise", "checked", "late", "zero", "verdict", "encl", "early max",
                    "early med", "ns/query");
  for (const ToiResult& m : c.methods) {
    const TimeTally& t = m.tally;
    if (t.checked == 0) {
      os << fmt::format("  {:<16} {:<16} {:>7}\n", m.name, to_string(m.promise), "n/a");
      continue;
    }
    // A never-late time is a lower bound: its t_hi (perhaps "no upper bound") encloses nothing
    // it promises, so its enclosure column is dropped.
    const std::string encl =
        m.promise == TimePromise::NeverLate ? "-" : std::to_string(t.not_enclosed + t.too_wide);
    os << fmt::format(
        "  {:<16} {:<16} {:>7} {:>7} {:>6} {:>7} {:>6} {:>10.3g} {:>10.3g} {:>10.1f}\n", m.name,
        to_string(m.promise), t.checked, t.late, t.zero, t.verdict_errors, encl, t.early_max(),
        t.early_median(), m.ns_per_query);
  }
}

}  // namespace

void add_time_counts(Json& j, const TimeTally& t) {
  j["checked"] = t.checked;
  j["contacts"] = t.contacts;
  j["late"] = t.late;
  j["zero"] = t.zero;
  j["verdict_errors"] = t.verdict_errors;
  j["not_enclosed"] = t.not_enclosed;
  j["too_wide"] = t.too_wide;
  j["not_a_time"] = t.garbage;
  j["no_answer"] = t.no_answer;
}

namespace {

Json methods_json(const ToiClassification& c) {
  Json methods = Json::object();
  for (const ToiResult& m : c.methods) {
    const TimeTally& t = m.tally;
    const bool any = t.checked > 0;
    Json& j = methods[m.name];
    j["promise"] = to_string(m.promise);
    add_time_counts(j, t);
    j["broken"] = t.broken;
    j["early_max"] = any ? Json(t.early_max()) : Json(nullptr);
    j["early_median"] = any ? Json(t.early_median()) : Json(nullptr);
    // Three decimals are more than the timing's precision.
    j["toi_ns_per_query"] = any ? Json(std::round(m.ns_per_query * 1e3) / 1e3) : Json(nullptr);
    j["na"] = m.na;
  }
  return methods;
}

std::string exact_text(double v) {
  for (int digits = 15; digits <= 17; ++digits) {
    const std::string s = fmt::format("{:.{}g}", v, digits);
    double r = 0;  // from_chars: the C locale's digits whatever LC_NUMERIC says
    std::from_chars(s.data(), s.data() + s.size(), r);
    if (r == v) return s;
  }
  return fmt::format("{:.17g}", v);
}

}  // namespace

void print_toi_table(std::ostream& os, const std::vector<FileToi>& files,
                     const ToiClassification& total) {
  if (files.size() > 1)
    for (const auto& [file, c] : files) print_block(os, file, c), os << "\n";
  print_block(os, files.size() > 1 ? "total" : files.front().first, total);
}

Json toi_json(const std::vector<FileToi>& files, const ToiClassification& total) {
  Json j = {{"width", total.width}, {"methods", methods_json(total)}, {"files", Json::array()}};
  for (const auto& [file, c] : files)
    j["files"].push_back({{"file", file}, {"methods", methods_json(c)}});
  return j;
}

std::string toi_csv_header(const ToiClassification& c) {
  std::string out;
  for (const ToiResult& m : c.methods) out += "," + m.name + " t_lo," + m.name + " t_hi";
  return out;
}

std::string toi_csv_fields(const ToiClassification& c, std::size_t i) {
  std::string out;
  for (const ToiResult& m : c.methods) {
    const Toi& t = m.said[i];
    if (!m.applies[i])
      out += ",n/a,n/a";
    else if (!t.hit)
      out += ",,";
    else
      out += "," + exact_text(t.t_lo) + "," + exact_text(t.t_hi);
  }
  return out;
}

}  // namespace fdh::verify
