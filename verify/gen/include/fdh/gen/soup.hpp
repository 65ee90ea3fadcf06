// Triangle soups for tree tests: 1 to max_tris triangles with dyadic corners in a small box,
// sometimes sharing corners as a mesh does, each corner moving by a small dyadic step from x0
// to x1. Many touching and near-touching boxes.
#pragma once

#include <cstdint>
#include <vector>

#include "fdh/bvh.hpp"

namespace fdh::verify {

struct Soup {
  std::vector<Tri> tris;
  std::vector<Vec3> x0, x1;
};

// Soup `seed`: the same seed gives the same soup. (As a RapidCheck generator: gen_soup in
// fdh/gen/rapidcheck.hpp.)
Soup generate_soup(int max_tris, std::uint64_t seed);

// Each primitive's corners at x0, and at x1 too when x1 is given (a swept primitive): the
// point sets whose exact k-DOPs the tree's leaves must contain.
std::vector<std::vector<Vec3>> primitive_corners(const std::vector<Tri>& tris,
                                                 const std::vector<Vec3>& x0,
                                                 const std::vector<Vec3>& x1);

}  // namespace fdh::verify
