// certify's metamorphic checks (certify_metamorphic.hpp).
#include "fdh/suite/certify_metamorphic.hpp"

#include <utility>

#include "fdh/check/metamorphic.hpp"

namespace fdh::verify {

MetamorphicCertifier::MetamorphicCertifier(std::vector<MetamorphicCheck>& rows,
                                           std::vector<Method> methods)
    : rows_(rows), methods_(std::move(methods)) {
  for (const Method& m : methods_) rows_.push_back({m.name, m.promise});
}

std::optional<std::string> MetamorphicCertifier::check(const Query& q) {
  std::optional<std::string> broken;
  const std::vector<Transformed> moved = transforms_of(q);
  for (std::size_t i = 0; i < methods_.size(); ++i) {
    std::optional<MetamorphicFailure> first;
    const MetamorphicCount n = count_metamorphic(methods_[i], q, moved, &first);
    rows_[i].checked += n.checked;
    rows_[i].violations += n.violations;
    if (first && rows_[i].held() && !broken)
      broken = describe(methods_[i], *first) + " (metamorphic)";
  }
  return broken;
}

}  // namespace fdh::verify
