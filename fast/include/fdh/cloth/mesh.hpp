// Triangle meshes for obstacles. The paper triangulates everything (§3.2 tests points against
// triangles), so a box or a sphere reaches the collision code as a closed mesh whose triangles
// are wound counter-clockwise seen from outside: the outward normal is (b - a) × (c - a).
#pragma once

#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/vec3.hpp"

namespace fdh::cloth {

struct TriMesh {
  std::vector<Vec3> x;
  std::vector<Tri> tris;

  // Appends `other`, renumbering its vertices.
  void append(const TriMesh& other);
};

// The closed box [lo, hi]: 8 vertices, 12 triangles.
TriMesh box_mesh(const Vec3& lo, const Vec3& hi);

// A sphere as a subdivided icosahedron: 20·4^level triangles with every vertex at distance r
// from the centre (up to rounding). Level 3 (1280 triangles) keeps every face within 0.4% of r.
TriMesh sphere_mesh(const Vec3& centre, double r, int level = 3);

// The unit outward normal of triangle t.
Vec3 unit_normal(const TriMesh& m, int t);

}  // namespace fdh::cloth
