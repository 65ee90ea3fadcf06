#include "patch_boundaries.hpp"

#include <algorithm>

#include "fdh/parallel/chunks.hpp"

namespace fdh::audit {

namespace {

// The corner index c of t whose edge t[c] -> t[c + 1] is longest (ties: the first).
int longest_edge(const Tri& t, const std::vector<Vec3>& x) {
  int best = 0;
  double longest = -1;
  for (int c = 0; c < 3; ++c) {
    const Vec3 d = x[t[(c + 1) % 3]] - x[t[c]];
    const double l = dot(d, d);
    if (l > longest) best = c, longest = l;
  }
  return best;
}

// Sorts the edges by their ends (either way round) and drops every edge met twice: a boundary's
// interior edges, each run once by either of its two triangles. Returns false if an edge is met
// twice the same way and same_way_fails (edges then unspecified).
bool drop_interior_edges(std::vector<Edge>& edges, bool same_way_fails) {
  const auto key = [](const Edge& e) {
    return std::make_pair(std::min(e[0], e[1]), std::max(e[0], e[1]));
  };
  std::sort(edges.begin(), edges.end(),
            [&](const Edge& a, const Edge& b) { return key(a) < key(b); });
  std::size_t out = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (i + 1 < edges.size() && key(edges[i]) == key(edges[i + 1])) {
      if (same_way_fails && edges[i] == edges[i + 1]) return false;
      ++i;
      continue;
    }
    edges[out++] = edges[i];
  }
  edges.resize(out);
  return true;
}

}  // namespace

std::vector<int> cell_partners(const MeshParts& mesh, const std::vector<Vec3>& x) {
  const int n = int(mesh.tris.size());
  // Each triangle's longest edge, undirected, with the triangle: sorted, a cell's two meet.
  std::vector<std::array<int, 3>> longest(n);
  for (int t = 0; t < n; ++t) {
    const Tri& f = mesh.tris[t];
    const int c = longest_edge(f, x), a = f[c], b = f[(c + 1) % 3];
    longest[t] = {std::min(a, b), std::max(a, b), t};
  }
  std::sort(longest.begin(), longest.end());
  std::vector<int> partner(n, -1);
  for (int i = 0; i + 1 < n; ++i) {
    const auto &p = longest[i], &q = longest[i + 1];
    if (p[0] != q[0] || p[1] != q[1]) continue;
    if ((i + 2 < n && longest[i + 2][0] == p[0] && longest[i + 2][1] == p[1]) ||
        !mesh.oriented[p[2]] || !mesh.oriented[q[2]])
      continue;  // a non-manifold or badly oriented edge: no cell
    partner[p[2]] = q[2];
    partner[q[2]] = p[2];
  }
  return partner;
}

PatchBoundaries::PatchBoundaries(const std::vector<NodeShape>& nodes, const MeshParts& mesh,
                                 const std::vector<int>& partner)
    : mesh_(&mesh), start_(nodes.size(), -1), length_(nodes.size(), 0) {
  if (nodes.empty()) return;
  for (int t = 0; t < int(mesh.tris.size()); ++t) {
    if (partner[t] < 0) continue;
    const Tri &f = mesh.tris[t], &g = mesh.tris[partner[t]];
    for (int c = 0; c < 3; ++c) {
      const int u = f[c], v = f[(c + 1) % 3];
      if (u != g[0] && u != g[1] && u != g[2]) continue;
      if (v != g[0] && v != g[1] && v != g[2]) continue;
      diagonal_.push_back({u, v, partner[t]});
    }
  }
  std::sort(diagonal_.begin(), diagonal_.end());
  // The subtrees at depth 6 on every core, each with loops of its own, then the nodes above.
  std::vector<int> roots;
  subtree_roots(nodes, 0, 0, roots);
  std::vector<Found> below(roots.size());
  std::vector<std::vector<int>> loops(roots.size());
  parallel::for_each_index(roots.size(), 1, [&](std::size_t r) {
    below[r].edges = boundary(nodes, roots[r], below[r].ok, loops[r], nullptr);
  });
  std::vector<int> root_of(nodes.size(), -1);
  for (std::size_t r = 0; r < roots.size(); ++r) {
    root_of[roots[r]] = int(r);
    const int offset = int(loops_.size());
    loops_.insert(loops_.end(), loops[r].begin(), loops[r].end());
    int end = roots[r];
    while (nodes[end].left >= 0) end = nodes[end].right;
    for (int i = roots[r]; i <= end; ++i)
      if (start_[i] >= 0) start_[i] += offset;
  }
  Stop stop{&root_of, &below};
  bool ok = true;
  boundary(nodes, 0, ok, loops_, &stop);
}

void PatchBoundaries::subtree_roots(const std::vector<NodeShape>& nodes, int node, int depth,
                                    std::vector<int>& out) {
  if (depth == 6 || nodes[node].left < 0) {
    out.push_back(node);
    return;
  }
  subtree_roots(nodes, nodes[node].left, depth + 1, out);
  subtree_roots(nodes, nodes[node].right, depth + 1, out);
}

// The node's directed boundary edges; ok false (and nothing returned) when the node holds a
// triangle that is not oriented consistently with its neighbours. Children's boundaries are
// merged: an edge in both, run in opposite directions, is inside the node.
std::vector<Edge> PatchBoundaries::boundary(const std::vector<NodeShape>& nodes, int node, bool& ok,
                                            std::vector<int>& loops, const Stop* stop) {
  if (stop && (*stop->root_of)[node] >= 0) {  // done below, on its own
    Found& f = (*stop->below)[(*stop->root_of)[node]];
    ok = f.ok;
    return std::move(f.edges);
  }
  const MeshParts& mesh = *mesh_;
  const NodeShape& n = nodes[node];
  std::vector<Edge> edges;
  if (n.left < 0) {
    ok = mesh.oriented[n.tri] != 0;
    if (!ok) return edges;
    const Tri& t = mesh.tris[n.tri];
    edges = {{t[0], t[1]}, {t[1], t[2]}, {t[2], t[0]}};
  } else {
    bool ok_left = true, ok_right = true;
    edges = boundary(nodes, n.left, ok_left, loops, stop);
    std::vector<Edge> right = boundary(nodes, n.right, ok_right, loops, stop);
    ok = ok_left && ok_right;
    if (!ok) return {};
    edges.insert(edges.end(), right.begin(), right.end());
    // Oriented triangles: an edge met twice is run both ways, and is interior.
    drop_interior_edges(edges, false);
  }
  keep_loop(node, edges, loops);
  return edges;
}

// Keeps the edges as an ordered loop when they form exactly one simple closed loop: every
// vertex starts at most one edge, and following the edges from the first visits them all.
// N's boundary made its cell completion's: across each boundary edge that is a cell's diagonal,
// the partner's edges are added, and edges met both ways cancel (triangles oriented alike).
void PatchBoundaries::complete_cells(std::vector<Edge>& edges) const {
  const std::size_t n = edges.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto it = std::lower_bound(diagonal_.begin(), diagonal_.end(),
                                     std::array<int, 3>{edges[i][0], edges[i][1], -1});
    if (it == diagonal_.end() || (*it)[0] != edges[i][0] || (*it)[1] != edges[i][1]) continue;
    const Tri& g = mesh_->tris[(*it)[2]];
    for (int c = 0; c < 3; ++c) edges.push_back({g[c], g[(c + 1) % 3]});
  }
  // The same way twice: no patch (never with oriented cells).
  if (!drop_interior_edges(edges, true)) edges.clear();
}

void PatchBoundaries::keep_loop(int node, std::vector<Edge> edges, std::vector<int>& loops) {
  complete_cells(edges);
  if (edges.size() < 3) return;
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    if (edges[i][0] == edges[i + 1][0]) return;  // a vertex the boundary passes twice
  const auto next = [&](int v) {
    const auto it = std::lower_bound(edges.begin(), edges.end(), Edge{v, -1});
    return it != edges.end() && (*it)[0] == v ? (*it)[1] : -1;
  };
  const int first = edges[0][0];
  const std::size_t start = loops.size();
  int v = first;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    loops.push_back(v);
    v = next(v);
    if (v < 0 || (v == first && k + 1 < edges.size())) {
      loops.resize(start);
      return;
    }
  }
  if (v != first) {
    loops.resize(start);
    return;
  }
  start_[node] = int(start);
  length_[node] = int(edges.size());
}

}  // namespace fdh::audit
