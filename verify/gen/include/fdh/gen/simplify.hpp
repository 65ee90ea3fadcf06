// Simplifying a failing query: shrinking's second greedy pass, over the Query itself. RapidCheck's
// shrink tree (shrink.hpp) shrinks what a construction drew; this pass then tries plain changes
// of the query and keeps each one that still fails: stop a vertex's motion (or a whole triangle's
// or edge's), take a common velocity out, move the case toward the origin, scale it by a power of
// two, write a coordinate with fewer bits. Every change it keeps makes the query strictly simpler
// (below), so it ends; the same query and predicate always give the same result.
#pragma once

#include <functional>

#include "fdh/query.hpp"

namespace fdh::verify {

using QueryFails = std::function<bool(const Query&)>;

// The digits of v written in binary fixed point: 0 for 0; for v = m 2^e with m odd, bitlen(m) + e
// when e >= 0 (an integer), else max(bitlen(m), -e) (3 -> 2, 0.75 -> 2, 2^-40 -> 40).
int binary_length(double v);

// How simple a query is, compared in this order: the vertices that move (x[i] != x[i + 4]), the
// total binary length of its 24 coordinates, the sum of their magnitudes.
struct Simplicity {
  int moving = 0;
  long length = 0;
  double magnitude = 0;
  bool operator<(const Simplicity& o) const;
};
Simplicity simplicity_of(const Query& q);

// The simpler queries tried from q, in the order tried: motion first, then the frame (velocity,
// translation, scale), then single coordinates. Each keeps q's kind and is exact: a translation
// or scale that would round a coordinate is not offered; a scale scales δ (min_distance) with
// the points, every other change keeps it. Not all are simpler than q.
std::vector<Query> simplifications(const Query& q);

// q simplified greedily while `fails` holds, at most `max_evaluations` calls of `fails`. q itself
// must fail; the result fails too and is q or simpler.
Query simplify_failure(Query q, const QueryFails& fails, int max_evaluations = 1500);

}  // namespace fdh::verify
