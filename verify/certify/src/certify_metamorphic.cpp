// certify's metamorphic checks (certify_metamorphic.hpp).
#include "fdh/certify/certify_metamorphic.hpp"

#include <utility>

#include "fdh/check/metamorphic.hpp"

namespace fdh::verify {
namespace {
// m on `moved`, one transformed query at a time while the budget lasts (a slow plug-in's calls
// take long); all at once without a budget.
MetamorphicCount count_within(const Method& m, bool before, const std::vector<Transformed>& moved,
                              std::optional<MetamorphicFailure>* first, const Budget& budget) {
  if (!budget.limited()) return count_metamorphic(m, before, moved, first);
  MetamorphicCount sum;
  for (const Transformed& t : moved) {
    if (budget.spent()) break;
    const MetamorphicCount n = count_metamorphic(m, before, {t}, first);
    sum.checked += n.checked, sum.violations += n.violations;
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

std::optional<std::string> MetamorphicCertifier::check(const Query& q, bool twin,
                                                       std::vector<MetamorphicCheck>& rows,
                                                       const Budget& budget) const {
  std::optional<std::string> broken;
  const std::vector<Transformed> moved = transforms_of(q);
  for (std::size_t i = 0; i < methods_.size(); ++i) {
    const Method& m = methods_[i];
    if (!m.applies_to(q) || budget.spent()) continue;
    std::optional<MetamorphicFailure> first;
    const bool before = m.is_twin ? twin : m.hit(q);
    const MetamorphicCount n = count_within(m, before, moved, &first, budget);
    rows[i].checked += n.checked;
    rows[i].violations += n.violations;
    if (first && rows[i].held() && !broken) broken = describe(m, *first) + " (metamorphic)";
  }
  return broken;
}

}  // namespace fdh::verify
