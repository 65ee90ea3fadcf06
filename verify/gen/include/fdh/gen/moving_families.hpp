// Generator families of moving queries (vertex-face with a moving triangle, and edge-edge),
// shared by the property tests and `fdhcert generate`. Dyadic coordinates, so the
// constructions are exact, and several know their truth (and contact time) without `exact`.
#pragma once

#include <rapidcheck.h>

#include <optional>
#include <string>
#include <vector>

#include "fdh/query.hpp"

namespace fdh::verify {

enum class MovingFamily {
  RandomLinear,   // vf or ee, every vertex anywhere in a small box at t = 0 and t = 1
  Generic,        // vf or ee, full-precision random coordinates: no exact coincidence, the
                  // speed case of a simulator's typical query
  Rotating,       // a triangle or edge turned about an axis, the turn replaced by straight lines
  Hourglass,      // Brochu et al. 2012: the triangle shrinks through a point and turns inside out
  TwoCrossings,   // the point meets the tilting plane twice; one meeting is inside, one is not
  Coplanar,       // every vertex in one plane throughout
  SlidingOnEdge,  // the point slides along the line of a triangle edge, on it or past its end
  ParallelEdges,  // ee: parallel edges whose lines coincide at t = 1/2, or miss by a hair
  DegenerateEdge  // ee: an edge that shrinks to a point at t = 1/2
};

const std::vector<MovingFamily>& all_moving_families();
std::string moving_family_name(MovingFamily f);
std::optional<MovingFamily> moving_family_by_name(const std::string& name);

struct GeneratedMoving {
  MovingFamily family;
  Query query;       // query.truth: 0 or 1 where the construction decides it, else -1
  std::string time;  // the exact earliest contact time it guarantees ("p/q"), or ""
};

rc::Gen<GeneratedMoving> gen_moving(MovingFamily f);

}  // namespace fdh::verify
