// Metamorphic checks, which need no oracle: transformations of a query that keep its truth. A
// method whose verdict changes under one of them is wrong on one of the two queries, whatever
// the truth is. Every transform is exact: where a coordinate would round, overflow or underflow,
// the transform does not apply to that query (and nothing is checked).
//
// The transforms (docs/methods.md, "Metamorphic checks"): time reversal (start and end swapped),
// the five other orders of the axes, a mirror, common dyadic translations, a common velocity
// (added to the end positions), scaling by powers of two, and relabelling: a triangle's corners
// turned or flipped, an edge's ends swapped, the two edges swapped.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

struct Transform {
  std::string name;  // "time-reversal", "axes-yzx", "scale-up", ...
  // The transformed query (same id, no truth), or nullopt where the transform does not apply:
  // another query kind, or a coordinate that would not be exact.
  std::function<std::optional<Query>(const Query&)> apply;
};

// Every transform, always in this order.
const std::vector<Transform>& all_transforms();

// The method's own verdict on a query it applies to (the twin entry's is the twin's).
bool verdict_of(const Method& m, const Query& q);

struct MetamorphicFailure {
  std::string transform;
  bool before = false, after = false;  // the method's verdict on q, and on the transformed q
};

// The first transform under which m's verdict on q changes, or nullopt. Transforms that do not
// apply to q, or give a query m makes no decision on, are skipped; so is q itself if m makes none.
std::optional<MetamorphicFailure> metamorphic_failure(const Method& m, const Query& q);

// q under every transform that applies to it, in order (ids and file names left out): made once
// for several methods.
struct Transformed {
  const Transform* transform = nullptr;
  Query query;
};
std::vector<Transformed> transforms_of(const Query& q);

// m on q under every transform that applies: how many were checked and how many changed its
// verdict; `first` (if given) gets the first change.
struct MetamorphicCount {
  long checked = 0, violations = 0;
};
// The same with m's verdict on q known already (`before`; m applies to q) and `moved` =
// transforms_of(q): made once for several methods.
MetamorphicCount count_metamorphic(const Method& m, bool before,
                                   const std::vector<Transformed>& moved,
                                   std::optional<MetamorphicFailure>* first = nullptr);
MetamorphicCount count_metamorphic(const Method& m, const Query& q,
                                   std::optional<MetamorphicFailure>* first = nullptr);

// "float-cubic says hit here and no after time-reversal": the words of a failure.
std::string describe(const Method& m, const MetamorphicFailure& f);

}  // namespace fdh::verify
