#include "fdh/check/findings.hpp"

#include <algorithm>
#include <optional>

namespace fdh::verify {
namespace {

std::string twin_name(const std::vector<Method>& methods) {
  for (const Method& m : methods)
    if (m.is_twin) return m.name;
  return "exact";
}

const Method& method_named(const std::vector<Method>& methods, const std::string& name) {
  return *std::find_if(methods.begin(), methods.end(),
                       [&](const Method& m) { return m.name == name; });
}

}  // namespace

std::string place_of(const QueryRecord& r, Place place) {
  const std::string line = r.file + ":" + std::to_string(r.line);
  return place == Place::Line ? line : line + " (query " + r.id + ")";
}

std::vector<Finding> findings(const Classification& c, const std::vector<QueryRecord>& records,
                              const std::vector<Method>& methods, Place place) {
  std::vector<Finding> out;
  const std::string twin = twin_name(all_methods());
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::optional<bool> agrees = twin_matches_truth(stated(records[i].truth), c.exact[i]);
    if (!agrees || *agrees) continue;
    out.push_back({i, twin, true, bool(c.exact[i]), Judgement::Broken,
                   twin + " disagrees with the file's truth at " + place_of(records[i], place)});
  }
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const Method& m = methods[k];
    if (m.is_twin) continue;
    const std::vector<char>& said = c.methods[k].verdict;
    for (std::size_t i = 0; i < records.size(); ++i) {
      if (said[i] == kNotApplicable || bool(said[i]) == bool(c.exact[i])) continue;
      out.push_back({i, m.name, false, bool(said[i]), judge(m.promise, said[i], c.exact[i]),
                     verdict_words(m, said[i], c.exact[i], place_of(records[i], place))});
    }
  }
  return out;
}

std::vector<TimeFinding> time_findings(const ToiClassification& toi,
                                       const std::vector<Method>& methods, double tolerance) {
  std::vector<TimeFinding> out;
  for (const ToiResult& r : toi.methods) {
    const Method& m = method_named(methods, r.name);
    for (std::size_t i = 0; i < r.checks.size(); ++i) {
      if (!r.applies[i]) continue;
      const TimeCheck& c = r.checks[i];
      const bool early = c.early > tolerance;
      if (!c.late && !c.zero && !early && c.kept) continue;
      out.push_back({i, r.name, r.promise, c, early, judge(m, c), judged_time_words(m, c)});
    }
  }
  return out;
}

}  // namespace fdh::verify
