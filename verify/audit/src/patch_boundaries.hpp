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
#pragma once

#include <vector>

#include "mesh_parts.hpp"

namespace fdh::audit {

// A tree node's shape: its children, or for a leaf (of one triangle) that triangle.
struct NodeShape {
  int left = -1, right = -1, tri = -1;
};

class PatchBoundaries {
 public:
  PatchBoundaries() = default;
  PatchBoundaries(const std::vector<NodeShape>& nodes, const MeshParts& mesh);

  bool has_loop(int node) const { return start_[node] >= 0; }
  // The loop's vertices in order (the edge from each to the next, and from the last to the
  // first); only for has_loop(node).
  const int* begin(int node) const { return loops_.data() + start_[node]; }
  const int* end(int node) const { return loops_.data() + start_[node] + length_[node]; }
  std::size_t size() const { return loops_.size(); }

 private:
  std::vector<Edge> boundary(const std::vector<NodeShape>& nodes, const MeshParts& mesh, int node,
                             bool& ok);
  void keep_loop(int node, std::vector<Edge> edges);

  std::vector<int> start_, length_, loops_;
};

}  // namespace fdh::audit
