// certify's metamorphic checks: every method of the registry under every transform
// (check/metamorphic.hpp), on each query certify draws (certify.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/suite/certify.hpp"

namespace fdh::verify {

class MetamorphicCertifier {
 public:
  // One row per method (by default every method of the registry), appended to `rows` (the
  // certificate's).
  explicit MetamorphicCertifier(std::vector<MetamorphicCheck>& rows,
                                std::vector<Method> methods = all_methods());

  // Counts every method on q; the words of the first verdict change of a method held to
  // invariance (MetamorphicCheck::held), if there is one.
  std::optional<std::string> check(const Query& q);

 private:
  std::vector<MetamorphicCheck>& rows_;
  std::vector<Method> methods_;
};

}  // namespace fdh::verify
