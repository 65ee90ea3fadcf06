// The workload shared by the tree benchmarks and the peers: the table scene
// (corpus/scenes/table.scene) at a chosen grid, run until the cloth drapes over the table, then
// one step's start and end positions. Every tree (ours, FCL's, Bullet's) is measured on exactly
// these positions against exactly this table (the obstacles grown by the skin, as the
// simulation collides with them).
#pragma once

#include <string>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/cloth/scene.hpp"
#include "fdh/mesh.hpp"

namespace fdh::bench {

struct ClothOnTable {
  int grid = 0;
  std::vector<Vec3> x0, x1;     // the particles at the start and end of one step
  std::vector<Tri> cloth_tris;  // the cloth's triangles
  TriMesh table;                // the collision mesh: the table grown by the skin
};

// Cached per grid: built once per run.
const ClothOnTable& cloth_on_table(int grid);

// A shipped scene, by its name in corpus/scenes/, with the grid set and the step made stable as
// `fdhcert simulate` makes it (0.9 times the stable step when the scene's is above it).
cloth::Scene shipped_scene(const std::string& name, int grid);

// Benchmark names: "<k>/<grid>" style argument lists.
inline const std::vector<int> kTreeGrids = {25, 50, 100, 200};

}  // namespace fdh::bench
