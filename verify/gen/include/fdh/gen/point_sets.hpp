// Point sets for bounding volumes: one set with full-precision coordinates (does a box contain
// the exact FDH of its points?), and pairs of sets built to touch exactly (do their boxes
// overlap?). Plain seeded generators: the same seed gives the same sets on every machine.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fdh/vec3.hpp"

namespace fdh::verify {

// 1 to 8 points around a centre up to 2^20 from the origin, spread over 2^-30 to 2^20 of it:
// coordinates that use all 53 bits, so that sums of them round.
std::vector<Vec3> random_point_set(std::uint64_t seed);

// Two sets whose exact hulls touch: set a lies on one side of a plane d·x = c, set b on the
// other, and each has a point on the plane (d one of the 13 integer directions of fdh/kdop.hpp,
// either sign). The two contact points differ by a step along the plane (exact: d·p = d·q), or
// are one shared point. Coordinates use all 53 bits.
struct TouchingSets {
  std::vector<Vec3> a, b;
  std::string contact;  // "shared point" or "plane (dx,dy,dz)"
};
TouchingSets touching_point_sets(std::uint64_t seed);

}  // namespace fdh::verify
