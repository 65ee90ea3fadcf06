// certify's metamorphic checks: every method of the registry under every transform
// (check/metamorphic.hpp), on each query certify draws (certify.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fdh/certify/certify.hpp"
#include "fdh/check/registry.hpp"

namespace fdh::verify {

class MetamorphicCertifier {
 public:
  // One row per method: by default every method of the registry.
  explicit MetamorphicCertifier(std::vector<Method> methods = all_methods());

  // The rows, in the methods' order, with nothing counted yet.
  std::vector<MetamorphicCheck> rows() const;

  // Counts every method on q into `rows` (rows()'s order); `twin` is the twin's verdict on q,
  // known already. Returns the words of the first verdict change of a method held to invariance
  // (MetamorphicCheck::held), if there is one. Safe to call from several threads at once (each
  // with its own rows) when the methods are (registry.hpp). Once `budget` is spent, stops
  // between two transformed queries (fdh/os/budget.hpp).
  std::optional<std::string> check(const Query& q, bool twin, std::vector<MetamorphicCheck>& rows,
                                   const Budget& budget = {}) const;

 private:
  std::vector<Method> methods_;
};

}  // namespace fdh::verify
