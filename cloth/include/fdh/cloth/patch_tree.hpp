// The cloth's grid as a tree of rectangular patches of cells, for the self-collision pass: each
// node a rectangle of cells, split across its longer side down to single cells. Every primitive
// (particle, triangle, edge) belongs to exactly one cell whose four corners hold its particles,
// so each pair of primitives meets either in one cell or in exactly one pair of sibling
// subtrees.
//
// Per step, a node is *flat* when its patch cannot touch itself during the step
// (fdh/normal_cone.hpp: every triangle's normal leans towards one direction for the whole step,
// and the patch's boundary stays a star-shaped contour around its centre along it). A flat node
// needs no test inside it: the self-collision pass then visits, before any contact, a few nodes
// near the root instead of every neighbouring pair of leaves.
#pragma once

#include <array>
#include <vector>

#include "fdh/cloth/cloth.hpp"
#include "fdh/cloth/parallel.hpp"
#include "fdh/kdop.hpp"
#include "fdh/normal_cone.hpp"

namespace fdh::cloth {

class PatchTree {
 public:
  struct Node {
    int r0, c0, r1, c1;  // cells [r0, r1) × [c0, c1)
    int left = -1, right = -1;
    bool leaf() const { return left < 0; }
  };

  explicit PatchTree(const Cloth& cloth);

  const std::vector<Node>& nodes() const { return nodes_; }
  int cell_of(const Node& n) const { return n.r0 * cols_ + n.c0; }  // for a leaf
  // What a cell owns: its particles, its two triangles, its edges (indices into the cloth's).
  const int* vertices_begin(int cell) const { return &vertex_[vertex_start_[cell]]; }
  const int* vertices_end(int cell) const { return &vertex_[vertex_start_[cell + 1]]; }
  const int* edges_begin(int cell) const { return &edge_[edge_start_[cell]]; }
  const int* edges_end(int cell) const { return &edge_[edge_start_[cell + 1]]; }
  static std::array<int, 2> triangles(int cell) { return {2 * cell, 2 * cell + 1}; }

  // Every node's swept normals for the step x0 -> x1 (bottom up, one pass over the triangles).
  void update_normals(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);

  // f(node) for every node, children before parents (BottomUp: on every core when large).
  template <class F>
  void bottom_up(const F& f) const {
    order_.run(f);
  }
  // Whether the node is flat over that step (its mask, then its contour): asked top down by the
  // pass, only of the nodes it reaches.
  bool flat(int node, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) const;

 private:
  int build(int r0, int c0, int r1, int c1);
  void own_primitives();
  void contour_of(const Node& n, std::vector<int>& out) const;

  const Cloth& cloth_;
  int grid_, cols_;  // particles per side, cells per side
  std::vector<Node> nodes_;
  BottomUp order_;  // bottom_up's order
  std::vector<int> vertex_, vertex_start_, edge_, edge_start_;
  std::vector<NormalBox> normals_;  // per node: its triangles' swept normals
  std::vector<Vec3> lean_;          // per node: sum of its triangles' normals at the end
};

}  // namespace fdh::cloth
