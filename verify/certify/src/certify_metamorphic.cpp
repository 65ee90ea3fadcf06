// certify's metamorphic checks (certify_metamorphic.hpp).
#include "fdh/certify/certify_metamorphic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "fdh/io/case_files.hpp"

namespace fdh::verify {
namespace {

// m on `moved`, one transformed query at a time: the budget is looked at between them (a slow
// plug-in's calls take long), and a call past --plugin-timeout is a broken promise on that
// transformed query (its words in `no_answer`, the first only).
MetamorphicCount count_within(const Method& m, bool before, const std::vector<Transformed>& moved,
                              bool twin, MetamorphicFirsts* first, const Budget& budget,
                              std::optional<std::pair<double, Transformed>>& no_answer) {
  MetamorphicCount sum;
  for (const Transformed& t : moved) {
    if (budget.spent()) break;
    MetamorphicCount n;
    try {
      n = count_metamorphic(m, before, {t}, twin, first);
    } catch (const NoAnswer& e) {
      n.checked = 1;
      n.judged = n.broken = m.promise != Promise::None;
      if (!no_answer && n.broken) no_answer.emplace(e.seconds, t);
    }
    sum.checked += n.checked, sum.violations += n.violations;
    sum.judged += n.judged, sum.broken += n.broken;
  }
  return sum;
}

// m's verdict on q: known already, asked, or nullopt when it gave none in time.
std::optional<bool> verdict_before(const Method& m, const Query& q, bool twin,
                                   const MetamorphicCertifier::Said& said) {
  if (m.is_twin) return twin;
  if (const auto known = said.find(m.name); known != said.end()) return known->second;
  try {
    return m.hit(q);
  } catch (const NoAnswer&) {
    return std::nullopt;
  }
}

}  // namespace

MetamorphicCertifier::MetamorphicCertifier(std::vector<Method> methods)
    : methods_(std::move(methods)) {}

std::vector<MetamorphicCheck> MetamorphicCertifier::rows() const {
  std::vector<MetamorphicCheck> rows;
  for (const Method& m : methods_) rows.push_back({m.name, m.promise});
  return rows;
}

std::optional<MetamorphicCertifier::Violation> MetamorphicCertifier::check(
    const Query& q, bool twin, std::vector<MetamorphicCheck>& rows,
    std::vector<TransformCount>& transforms, const Budget& budget, const Said& said) const {
  std::optional<Violation> found;
  if (methods_.empty()) return found;  // the metamorphic stage is not run (--stages)
  const std::vector<Transformed> moved = transforms_of(q, &transforms);
  for (std::size_t i = 0; i < methods_.size(); ++i) {
    const Method& m = methods_[i];
    if (!m.applies_to(q) || budget.spent()) continue;
    const std::optional<bool> before = verdict_before(m, q, twin, said);
    if (!before) continue;  // no answer on q itself: the promise check counted it
    MetamorphicFirsts first;
    std::optional<std::pair<double, Transformed>> no_answer;
    const MetamorphicCount n = count_within(m, *before, moved, twin, &first, budget, no_answer);
    MetamorphicCheck& row = rows[i];
    row.checked += n.checked, row.violations += n.violations;
    row.judged += n.judged, row.broken += n.broken;
    if (found) continue;
    const std::string kind = " (metamorphic, " + std::string(to_string(decision_of(q))) + ")";
    if (first.broken)
      found = Violation{describe(m, *first.broken) + " (metamorphic, " +
                            to_string(decision_of(first.broken->moved)) + ")",
                        first.broken->moved, first.broken->transform, m.name};
    else if (no_answer)
      found = Violation{m.name + " gives no answer in " + fmt::format("{:g}", no_answer->first) +
                            " s on the query after " + no_answer->second.transform->name + " " +
                            judgement_words(Judgement::Broken, m.promise) + kind,
                        no_answer->second.query, no_answer->second.transform->name, m.name};
    else if (first.changed && row.held())
      found = Violation{describe(m, *first.changed) + " (metamorphic)", q, "", m.name};
  }
  return found;
}

std::string MetamorphicCertifier::Violation::before(const QueryRecord& original) const {
  if (transform.empty()) return "";
  std::string line = case_file_text(original, {});
  while (!line.empty() && line.back() == '\n') line.pop_back();
  // One comment line: a query at δ > 0 comes after its `min-distance` line.
  std::replace(line.begin(), line.end(), '\n', ' ');
  return "before " + transform + ": " + line;
}

std::optional<MetamorphicCertifier::Violation> MetamorphicCertifier::check(
    const Query& q, bool twin, std::vector<MetamorphicCheck>& rows) const {
  std::vector<TransformCount> transforms = transform_counts();
  return check(q, twin, rows, transforms);
}

}  // namespace fdh::verify
