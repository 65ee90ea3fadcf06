// Meshes and sequences for the audit's tests: grids, and a brute-force audit (every pair, the
// exact twins alone) to compare the engine with.
#pragma once

#include <vector>

#include "fdh/audit/auditor.hpp"

namespace fdh::audit::testing {

struct Mesh {
  std::vector<Vec3> x;
  std::vector<Tri> tris;
};

// An n x n grid of vertices, `spacing` apart from `origin` in x and y, counter-clockwise seen
// from +z (normals up).
Mesh grid(int n, double spacing, const Vec3& origin);

// a's vertices then b's, b's triangles renumbered.
Mesh join(const Mesh& a, const Mesh& b);

// m as the whole cloth, with no obstacle.
Topology cloth_only(const Mesh& m);

// Every violation of the step x0 -> x1 (vertex-face, edge-edge) and of the frame x1, by the
// exact twins over all pairs, in report order (TOIs from robust_ccd_toi, like the engine).
std::vector<Violation> brute_force(const Topology& topology, const std::vector<Vec3>& x0,
                                   const std::vector<Vec3>& x1, const std::vector<Vec3>& y0,
                                   const std::vector<Vec3>& y1, int frame, bool step);

}  // namespace fdh::audit::testing
