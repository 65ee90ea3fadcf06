// certify's metamorphic checks: every method of the registry under every transform
// (check/metamorphic.hpp), on each query certify draws (certify.cpp).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fdh/certify/certify.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/io/query_record.hpp"

namespace fdh::verify {

class MetamorphicCertifier {
 public:
  // One row per method: by default every method of the registry.
  explicit MetamorphicCertifier(std::vector<Method> methods = all_methods());

  // The rows, in the methods' order, with nothing counted yet.
  std::vector<MetamorphicCheck> rows() const;

  // A broken promise under a transform (or a verdict change of a method held to invariance):
  // its words, naming the method, the transform and the decision, and the query to save (the
  // transformed one for a broken promise, q itself for a verdict change).
  struct Violation {
    std::string what;
    Query saved;
    std::string transform;  // the transform saved is of q, or "" when saved is q
    std::string method;     // the method whose promise it breaks

    // A comment for the saved case: the query as drawn (`original`, q's record), in the native
    // format, before the transform; "" when saved is q.
    std::string before(const QueryRecord& original) const;
  };

  // Counts every method on q into `rows` (rows()'s order) and q's transforms into `transforms`
  // (transform_counts()'s order); `twin` is the twin's verdict on q, known already, which every
  // transform keeps. Returns the first violation: of the methods in order, a promise broken
  // under a transform, else a verdict change of a method held to invariance
  // (MetamorphicCheck::held). Safe to call from several threads at once (each with its own rows)
  // when the methods are (registry.hpp). Once `budget` is spent, stops between two transformed
  // queries (fdh/os/budget.hpp).
  // `said` holds the verdicts on q known already, by method name (nullopt: no answer within
  // --plugin-timeout, and the method is left out on q); the others are asked. A transformed
  // query a plug-in gives no answer on (NoAnswer) is a broken promise of its method.
  using Said = std::map<std::string, std::optional<bool>>;
  std::optional<Violation> check(const Query& q, bool twin, std::vector<MetamorphicCheck>& rows,
                                 std::vector<TransformCount>& transforms, const Budget& budget = {},
                                 const Said& said = {}) const;
  // The same without the transforms' counts.
  std::optional<Violation> check(const Query& q, bool twin,
                                 std::vector<MetamorphicCheck>& rows) const;

 private:
  std::vector<Method> methods_;
};

}  // namespace fdh::verify
