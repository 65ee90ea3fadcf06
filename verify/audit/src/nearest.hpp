// The nearest pair of triangles of a frame (`audit --min-distance`): a floating-point estimate
// of each pair's distance chooses it, and its distance is then computed exactly
// (fdh/exact/distance.hpp), so the summary can say "kept 0.0149, promised 0.015" with an exact
// enclosure and the place.
#pragma once

#include <cmath>
#include <tuple>

#include "fdh/audit/auditor.hpp"
#include "fdh/triangle_triangle.hpp"

namespace fdh::audit {

// The distance between two triangles that do not meet, in doubles (closest points: Ericson,
// Real-Time Collision Detection, 2005, secs. 5.1.5 and 5.1.9): an estimate, never a decision.
double distance_estimate(const Triangle3& a, const Triangle3& b);

// A candidate for the frame's nearest pair: its estimate and its name, ordered by both so that
// the choice is the same for any thread count.
struct NearestCandidate {
  double estimate = HUGE_VAL;
  int kind = 0, a = -1, b = -1;
  bool operator<(const NearestCandidate& o) const {
    return std::tie(estimate, kind, a, b) < std::tie(o.estimate, o.kind, o.a, o.b);
  }
};

// The exact distance of the chosen pair, at positions x (cloth) and y (obstacles).
Nearest nearest_of(const NearestCandidate& c, int frame, const Topology& t,
                   const std::vector<Vec3>& x, const std::vector<Vec3>& y);

}  // namespace fdh::audit
