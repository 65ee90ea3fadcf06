#include "patch_boundaries.hpp"

#include <algorithm>

namespace fdh::audit {

PatchBoundaries::PatchBoundaries(const std::vector<NodeShape>& nodes, const MeshParts& mesh)
    : start_(nodes.size(), -1), length_(nodes.size(), 0) {
  if (nodes.empty()) return;
  bool ok = true;
  boundary(nodes, mesh, 0, ok);
}

// The node's directed boundary edges; ok false (and nothing returned) when the node holds a
// triangle that is not oriented consistently with its neighbours. Children's boundaries are
// merged: an edge in both, run in opposite directions, is inside the node.
std::vector<Edge> PatchBoundaries::boundary(const std::vector<NodeShape>& nodes,
                                            const MeshParts& mesh, int node, bool& ok) {
  const NodeShape& n = nodes[node];
  std::vector<Edge> edges;
  if (n.left < 0) {
    ok = mesh.oriented[n.tri] != 0;
    if (!ok) return edges;
    const Tri& t = mesh.tris[n.tri];
    edges = {{t[0], t[1]}, {t[1], t[2]}, {t[2], t[0]}};
  } else {
    bool ok_left = true, ok_right = true;
    edges = boundary(nodes, mesh, n.left, ok_left);
    std::vector<Edge> right = boundary(nodes, mesh, n.right, ok_right);
    ok = ok_left && ok_right;
    if (!ok) return {};
    edges.insert(edges.end(), right.begin(), right.end());
    const auto key = [](const Edge& e) {
      return std::make_pair(std::min(e[0], e[1]), std::max(e[0], e[1]));
    };
    std::sort(edges.begin(), edges.end(),
              [&](const Edge& a, const Edge& b) { return key(a) < key(b); });
    std::size_t out = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      // Oriented triangles: an edge met twice is run both ways, and is interior.
      if (i + 1 < edges.size() && key(edges[i]) == key(edges[i + 1])) {
        ++i;
        continue;
      }
      edges[out++] = edges[i];
    }
    edges.resize(out);
  }
  keep_loop(node, edges);
  return edges;
}

// Keeps the edges as an ordered loop when they form exactly one simple closed loop: every
// vertex starts at most one edge, and following the edges from the first visits them all.
void PatchBoundaries::keep_loop(int node, std::vector<Edge> edges) {
  if (edges.size() < 3) return;
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    if (edges[i][0] == edges[i + 1][0]) return;  // a vertex the boundary passes twice
  const auto next = [&](int v) {
    const auto it = std::lower_bound(edges.begin(), edges.end(), Edge{v, -1});
    return it != edges.end() && (*it)[0] == v ? (*it)[1] : -1;
  };
  const int first = edges[0][0];
  const std::size_t start = loops_.size();
  int v = first;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    loops_.push_back(v);
    v = next(v);
    if (v < 0 || (v == first && k + 1 < edges.size())) {
      loops_.resize(start);
      return;
    }
  }
  if (v != first) {
    loops_.resize(start);
    return;
  }
  start_[node] = int(start);
  length_[node] = int(edges.size());
}

}  // namespace fdh::audit
