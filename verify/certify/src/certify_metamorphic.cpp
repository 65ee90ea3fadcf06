// certify's metamorphic checks (certify_metamorphic.hpp).
#include "fdh/certify/certify_metamorphic.hpp"

#include <utility>

#include "fdh/check/metamorphic.hpp"

namespace fdh::verify {

MetamorphicCertifier::MetamorphicCertifier(std::vector<Method> methods)
    : methods_(std::move(methods)) {}

std::vector<MetamorphicCheck> MetamorphicCertifier::rows() const {
  std::vector<MetamorphicCheck> rows;
  for (const Method& m : methods_) rows.push_back({m.name, m.promise});
  return rows;
}

std::optional<std::string> MetamorphicCertifier::check(const Query& q, bool twin,
                                                       std::vector<MetamorphicCheck>& rows) const {
  std::optional<std::string> broken;
  const std::vector<Transformed> moved = transforms_of(q);
  for (std::size_t i = 0; i < methods_.size(); ++i) {
    const Method& m = methods_[i];
    if (!m.applies_to(q)) continue;
    std::optional<MetamorphicFailure> first;
    const bool before = m.is_twin ? twin : m.hit(q);
    const MetamorphicCount n = count_metamorphic(m, before, moved, &first);
    rows[i].checked += n.checked;
    rows[i].violations += n.violations;
    if (first && rows[i].held() && !broken) broken = describe(m, *first) + " (metamorphic)";
  }
  return broken;
}

}  // namespace fdh::verify
