// certify's metamorphic checks: every method of the registry under every transform
// (check/metamorphic.hpp), on each query certify draws. Private to fdh_suite (certify.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/suite/certify.hpp"

namespace fdh::verify {

class MetamorphicCertifier {
 public:
  // One row per method of the registry, appended to `rows` (the certificate's).
  explicit MetamorphicCertifier(std::vector<MetamorphicCheck>& rows);

  // Counts every method on q; the words of the first verdict change of a method with a promise,
  // if there is one.
  std::optional<std::string> check(const Query& q);

 private:
  std::vector<MetamorphicCheck>& rows_;
  std::vector<Method> methods_ = all_methods();
};

}  // namespace fdh::verify
