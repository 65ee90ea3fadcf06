// Which nodes of a triangle tree can be flat (fdh/normal_cone.hpp), and their boundary: computed
// once for the sequence, since the topology is fixed. A node's boundary is the set of its edges
// with exactly one incident triangle in the node, each run in its triangle's direction; a node
// can be flat only when its triangles are oriented consistently (mesh_parts.hpp's `oriented`)
// and that boundary is exactly one closed loop, here in order (counter-clockwise seen from the
// triangles' normals, as contour_is_star_shaped wants it). One loop suffices whatever the
// genus: the degree of the projection along d at a point equals the winding number of the
// projected loop around it, and every triangle counts positively (all lean towards d), so a
// loop that winds once leaves every point at most one preimage, with no assumption on the
// topology inside (a patch with handles simply never passes).
//
// Cells: a spatial tree splits a triangulated grid between the two triangles of a cell as often
// as along its lines, and the boundary then zigzags (a sawtooth), which no contour test around a
// centre accepts. So each node is tested as its *cell completion* N' = N + the partner of each
// of its triangles (partners: two triangles across their common longest edge, mutually, at the
// first frame: a grid's cells). N' is a superset of N, so N' flat implies N flat; its boundary
// is N's with each partner added across its diagonal, and runs along the cells' sides.
#pragma once

#include <array>
#include <vector>

#include "mesh_parts.hpp"

namespace fdh::audit {

// A tree node's shape: its children, or for a leaf (of one triangle) that triangle.
struct NodeShape {
  int left = -1, right = -1, tri = -1;
};

// Per triangle, the triangle across its longest edge (at positions x) when that one's longest edge
// is the same one and both are oriented; else -1.
std::vector<int> cell_partners(const MeshParts& mesh, const std::vector<Vec3>& x);

class PatchBoundaries {
 public:
  PatchBoundaries() = default;
  // partner: per triangle, the other triangle of its cell, or -1 (cell_partners()).
  PatchBoundaries(const std::vector<NodeShape>& nodes, const MeshParts& mesh,
                  const std::vector<int>& partner);

  bool has_loop(int node) const { return start_[node] >= 0; }
  // The loop of the node's cell completion: its vertices in order (the edge from each to the next,
  // and from the last to the first); only for has_loop(node).
  const int* begin(int node) const { return loops_.data() + start_[node]; }
  const int* end(int node) const { return loops_.data() + start_[node] + length_[node]; }
  std::size_t size() const { return loops_.size(); }

 private:
  // A subtree's boundary, computed on its own (on a core of its own) before the nodes above.
  struct Found {
    std::vector<Edge> edges;
    bool ok = true;
  };
  struct Stop {  // where the pass above stops: the subtrees done below
    const std::vector<int>* root_of;
    std::vector<Found>* below;
  };
  static void subtree_roots(const std::vector<NodeShape>& nodes, int node, int depth,
                            std::vector<int>& out);
  // The node's directed boundary, its loop (if one) appended to `loops`.
  std::vector<Edge> boundary(const std::vector<NodeShape>& nodes, int node, bool& ok,
                             std::vector<int>& loops, const Stop* stop);
  void keep_loop(int node, std::vector<Edge> edges, std::vector<int>& loops);
  void complete_cells(std::vector<Edge>& edges) const;

  const MeshParts* mesh_ = nullptr;
  std::vector<std::array<int, 3>> diagonal_;  // (u, v, p): u -> v is a cell diagonal, p's partner's
  std::vector<int> start_, length_, loops_;
};

}  // namespace fdh::audit
