// A triangle mesh in plain doubles: the obstacles of a cloth scene, and what the exact audit
// checks against. The paper triangulates everything (§3.2 tests points against triangles), so
// a closed mesh's triangles are wound counter-clockwise seen from outside: the outward normal
// is (b - a) × (c - a).
#pragma once

#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/vec3.hpp"

namespace fdh {

struct TriMesh {
  std::vector<Vec3> x;
  std::vector<Tri> tris;

  // Appends `other`, renumbering its vertices.
  void append(const TriMesh& other);
};

// The unit outward normal of triangle t.
Vec3 unit_normal(const TriMesh& m, int t);

}  // namespace fdh
