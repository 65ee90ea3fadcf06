// Generator families of static vertex-face queries, shared by the property tests and the
// fuzzer. Coordinates are dyadic (small integers over powers of two), so a path that passes
// exactly through an edge or a vertex really does, and the construction often knows the truth
// on its own: an oracle that does not depend on `exact`.
#pragma once

#include <rapidcheck.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

enum class Family {
  ParallelCross,    // BB' along the normal, crossing the plane
  ParallelShort,    // ... stopping short of it
  ParallelLand,     // ... landing exactly on it
  ParallelStart,    // ... starting on it
  Angled,           // at an angle to the normal, crossing or not
  ThroughEdge,      // through a point of an edge, exactly
  ThroughVertex,    // through a vertex, exactly
  HairOutsideEdge,  // through a point 2^-30 outside an edge
  InPlane,          // the whole motion in the triangle's plane
  ZeroMotion,       // B' = B
  Grazing,          // B' ends 2^-20 to 2^-45 (times |n|) from the plane, on either side
  FarFromOrigin,    // one of the above translated by up to 2^42
  Tiny,             // one of the above scaled by 2^-20 to 2^-60
  Sliver,           // F within 2^-10 to 2^-40 of line DE (never on it)
  Degenerate,       // zero-area triangles: collinear or coincident corners
};

const std::vector<Family>& all_families();
std::string family_name(Family f);
std::optional<Family> family_by_name(const std::string& name);

struct Generated {
  Family family;
  Query query;       // query.truth: 0 or 1 where the construction decides it, else -1
  std::string kind;  // the contact kind the construction guarantees ("edge", ...), or ""
  std::string time;  // the exact contact time it guarantees ("p/q"), or ""
};

rc::Gen<Generated> gen_family(Family f);

// For RapidCheck's counterexample output: the query as a native-format line.
void showValue(const Generated& g, std::ostream& os);

// A triangle soup for tree tests: 1 to max_tris triangles with dyadic corners in a small box,
// sometimes sharing corners as a mesh does, each corner moving by a small dyadic step from x0
// to x1. Many touching and near-touching boxes.
struct Soup {
  std::vector<Tri> tris;
  std::vector<Vec3> x0, x1;
};
rc::Gen<Soup> gen_soup(int max_tris);

// Each primitive's corners at x0, and at x1 too when x1 is given (a swept primitive): the
// point sets whose exact k-DOPs the tree's leaves must contain.
std::vector<std::vector<Vec3>> primitive_corners(const std::vector<Tri>& tris,
                                                 const std::vector<Vec3>& x0,
                                                 const std::vector<Vec3>& x1);

}  // namespace fdh::verify
