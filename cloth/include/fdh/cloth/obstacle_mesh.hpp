// Obstacle meshes: a box or a sphere reaches the collision code as a closed fdh::TriMesh.
#pragma once

#include <vector>

#include "fdh/mesh.hpp"

namespace fdh::cloth {

// The closed box [lo, hi]: 8 vertices, 12 triangles.
TriMesh box_mesh(const Vec3& lo, const Vec3& hi);

// A sphere as a subdivided icosahedron: 20·4^level triangles with every vertex at distance r
// from the centre (up to rounding). Level 3 (1280 triangles) keeps every face within 0.4% of r.
TriMesh sphere_mesh(const Vec3& centre, double r, int level = 3);

}  // namespace fdh::cloth
