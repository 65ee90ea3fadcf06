// certify's metamorphic checks (certify_metamorphic.hpp).
#include "fdh/certify/certify_metamorphic.hpp"

#include <algorithm>
#include <utility>

#include "fdh/io/case_files.hpp"

namespace fdh::verify {
namespace {

// m on `moved`, one transformed query at a time while the budget lasts (a slow plug-in's calls
// take long); all at once without a budget.
MetamorphicCount count_within(const Method& m, bool before, const std::vector<Transformed>& moved,
                              bool twin, MetamorphicFirsts* first, const Budget& budget) {
  if (!budget.limited()) return count_metamorphic(m, before, moved, twin, first);
  MetamorphicCount sum;
  for (const Transformed& t : moved) {
    if (budget.spent()) break;
    const MetamorphicCount n = count_metamorphic(m, before, {t}, twin, first);
    sum.checked += n.checked, sum.violations += n.violations;
    sum.judged += n.judged, sum.broken += n.broken;
  }
  return sum;
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
    std::vector<TransformCount>& transforms, const Budget& budget) const {
  std::optional<Violation> found;
  const std::vector<Transformed> moved = transforms_of(q, &transforms);
  for (std::size_t i = 0; i < methods_.size(); ++i) {
    const Method& m = methods_[i];
    if (!m.applies_to(q) || budget.spent()) continue;
    MetamorphicFirsts first;
    const bool before = m.is_twin ? twin : m.hit(q);
    const MetamorphicCount n = count_within(m, before, moved, twin, &first, budget);
    MetamorphicCheck& row = rows[i];
    row.checked += n.checked, row.violations += n.violations;
    row.judged += n.judged, row.broken += n.broken;
    if (found) continue;
    if (first.broken)
      found = Violation{describe(m, *first.broken) + " (metamorphic, " +
                            to_string(decision_of(first.broken->moved)) + ")",
                        first.broken->moved, first.broken->transform};
    else if (first.changed && row.held())
      found = Violation{describe(m, *first.changed) + " (metamorphic)", q, ""};
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
