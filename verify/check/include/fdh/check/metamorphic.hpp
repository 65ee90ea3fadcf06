// Metamorphic checks, which need no oracle: transformations of a query that keep its truth. A
// method whose verdict changes under one of them is wrong on one of the two queries, whatever
// the truth is. Every transform is exact: where a coordinate would round, overflow or leave the
// normal range, the transform does not apply to that query (it is skipped, and counted so).
//
// Because every transform keeps the exact verdict, the exact twin's verdict on a query is also
// its verdict on each transform of it: a method that promises CONSERVATIVE or EXACT is judged
// on every transformed query against that verdict, through the checker (checker.hpp).
//
// The transforms (docs/methods.md, "Metamorphic checks"): time reversal (start and end swapped),
// the five other orders of the axes, a mirror, common dyadic translations from 2^-60 to 2^60, a
// common velocity (added to the end positions), scaling by powers of two from 2^-60 to 2^60, and
// relabelling: a triangle's corners turned or flipped, an edge's ends swapped, the two edges
// swapped. A query's minimum separation δ (Query::min_distance) is a distance: the scales
// multiply it by their power of two (skipped where that is not exact, as for the points), every
// other transform keeps it (time reversal keeps the verdict, not t*_δ).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

struct Transform {
  std::string name;  // "time-reversal", "axes-yzx", "scale-up", "scale-2^40", ...
  // The one query kind it is for (the relabellings), or nullopt: every kind.
  std::optional<QueryKind> kind;
  // The transformed query (same id, no truth), or nullopt where the transform does not apply:
  // another query kind, or a coordinate that would round, overflow or leave the normal range.
  std::function<std::optional<Query>(const Query&)> apply;

  bool for_kind(const Query& q) const { return !kind || *kind == q.kind; }
};

// Every transform, always in this order.
const std::vector<Transform>& all_transforms();

// The method's own verdict on a query it applies to (the twin entry's is the twin's).
bool verdict_of(const Method& m, const Query& q);

// Whether m is judged against its promise under the transforms: a promise (EXACT or
// CONSERVATIVE), and not the twin itself (whose verdict is the one judged against).
bool judged_under_transforms(const Method& m);

struct MetamorphicFailure {
  std::string transform;
  bool before = false, after = false;  // the method's verdict on q, and on the transformed q
  // With the exact verdict of q known (the twin's, which every transform keeps): it, and whether
  // `after` keeps the method's promise against it (checker.hpp keeps_promise).
  std::optional<bool> twin;
  bool kept = true;
  Query moved;  // the transformed query
};

// The first transform under which m's verdict on q changes, or nullopt. Transforms that do not
// apply to q, or give a query m makes no decision on, are skipped; so is q itself if m makes none.
std::optional<MetamorphicFailure> metamorphic_failure(const Method& m, const Query& q);

// The first transform under which m's verdict breaks its promise against `twin`, the exact
// verdict of q (and so of every transform of q), or nullopt; always nullopt for a method not
// judged_under_transforms. The second form computes the twin (only when m is judged).
std::optional<MetamorphicFailure> promise_failure(const Method& m, const Query& q, bool twin);
std::optional<MetamorphicFailure> promise_failure(const Method& m, const Query& q);

// q under every transform that applies to it, in order (ids and file names left out): made once
// for several methods.
struct Transformed {
  const Transform* transform = nullptr;
  Query query;
};
// How often each transform applied, and was skipped as inexact (all_transforms()'s order; a
// transform for another query kind is neither).
struct TransformCount {
  std::string transform;
  long applied = 0, skipped = 0;
};
std::vector<TransformCount> transform_counts();  // every transform, counts 0
// With `counts` (transform_counts()'s size), q's transforms are counted into it.
std::vector<Transformed> transforms_of(const Query& q,
                                       std::vector<TransformCount>* counts = nullptr);

// m on q under every transform that applies: how many were checked and how many changed its
// verdict; with the exact verdict known and m judged_under_transforms, how many were judged
// against its promise and how many broke it.
struct MetamorphicCount {
  long checked = 0, violations = 0;
  long judged = 0, broken = 0;
};
// The first verdict change and the first broken promise found.
struct MetamorphicFirsts {
  std::optional<MetamorphicFailure> changed, broken;
};
// The same with m's verdict on q known already (`before`; m applies to q), `moved` =
// transforms_of(q) (made once for several methods) and `twin` the exact verdict of q, if known.
MetamorphicCount count_metamorphic(const Method& m, bool before,
                                   const std::vector<Transformed>& moved, std::optional<bool> twin,
                                   MetamorphicFirsts* first = nullptr);
MetamorphicCount count_metamorphic(const Method& m, bool before,
                                   const std::vector<Transformed>& moved,
                                   std::optional<MetamorphicFailure>* first = nullptr);
MetamorphicCount count_metamorphic(const Method& m, const Query& q,
                                   std::optional<MetamorphicFailure>* first = nullptr);

// "float-cubic says hit here and no after time-reversal", or for a broken promise the checker's
// words and the transform ("aabb says no, the exact twin says hit: misses a hit (breaks
// CONSERVATIVE) on the query after scale-2^40"): the words of a failure.
std::string describe(const Method& m, const MetamorphicFailure& f);

// What fuzz --metamorphic looks for in q: "broken-promise" (m judged_under_transforms and its
// answer breaks its promise under some transform, against the twin's verdict on q),
// "metamorphic" (its verdict changes under some transform), "" for neither.
std::string metamorphic_finding(const Method& m, const Query& q);
// The first failure of that class on q: the broken promise, else the verdict change.
std::optional<MetamorphicFailure> metamorphic_finding_failure(const Method& m, const Query& q);

}  // namespace fdh::verify
