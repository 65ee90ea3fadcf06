// `exact` continuous collision detection: do a point and a triangle (vertex-face) or two edges
// (edge-edge), each vertex moving linearly over the step, touch at some time in [0, 1]?
// Closed primitives, touching counts. Exact on exactly the given doubles in every case: several
// contacts in one step (the point crossing the plane twice, the "hourglass"), coplanar for the
// whole step, triangles or edges of zero size at some time, no motion at all.
//
// The algebra (docs/methods.md): contact needs coplanarity, a cubic in t. If the cubic is not
// identically zero, only its roots in [0, 1] can be contacts; they are isolated by Bernstein
// bisection (Sturm sequences where that does not finish) and the inside test is decided by
// exact signs at each root. If it is identically zero, the first contact is at the start or where a
// vertex meets an edge, and the same reasoning recurses to point-edge and point-point problems.
// Exact integers throughout: machine integers while they fit, GMP's mpn layer on limbs kept inline
// beyond: heap allocation only for integers beyond 768 bits (reference/src/integer.hpp,
// inline_vector.hpp).
//
// Minimum separation (issue 30): with q.min_distance = δ > 0, every function below answers the
// same question within Euclidean distance δ instead of at contact (closed primitives, δ at its
// exact value, t*_δ the earliest time within δ), with the same contracts: exact verdicts, the
// same enclosures of t*_δ. The algebra is reference/src/exact_separation.cpp (docs/methods.md,
// "Minimum separation"). δ = 0 takes the contact path, unchanged; a δ that is negative, NaN or
// infinite is refused with std::invalid_argument.
#pragma once

#include <string>

#include "fdh/ccd/toi.hpp"
#include "fdh/query.hpp"

namespace fdh::exact {

struct CcdOptions {
  double t0 = 0, t1 = 1;  // the time window searched, 0 <= t0 <= t1 <= 1
  // Refine the contact time to width < 2^-time_bits (0: as isolated, possibly all of [t0, t1]).
  // Bisection from [t0, t1] lands exactly on dyadic times with few bits, such as 1/2 or 3/8.
  int time_bits = 52;
};

struct CcdContact {
  bool hit = false;
  // The earliest contact lies in the closed interval [time_lo, time_hi]; time_lo == time_hi
  // when it is known exactly (a rational). Exact decimal fractions "p/q"; "" without a hit.
  std::string time_lo, time_hi;
  double time_lo_down = 0, time_hi_up = 0;  // the same bounds rounded outward to doubles
  bool time_exact() const { return hit && time_lo == time_hi; }
};

// Vertex-face or edge-edge by q.kind (fdh/query.hpp gives the point order).
CcdContact ccd(const Query& q, const CcdOptions& options = {});

// The verdict alone: the fallback of fast/'s `robust` moving test.
bool ccd_hit(const Query& q);

// The exact verdict and an enclosure of the earliest contact t* no wider than `width`, searched
// in [t0, t1] (fdh/ccd/toi.hpp's ExactToi: the fallback of fast/'s robust_ccd_toi), with
// t_lo > 0 unless t* = 0. kMinToiWidth <= width <= 1, else std::invalid_argument.
Toi ccd_toi(const Query& q, double t0, double t1, double width);

// Where a time t in [0, 1] lies against the exact earliest contact t* of a query that has one:
// -1 for t < t*, 0 for t == t*, +1 for t > t*, decided exactly. The twin of the TOI decisions
// ("late" is +1). Throws std::invalid_argument for a query without contact.
int compare_with_toi(const Query& q, double t);

}  // namespace fdh::exact
