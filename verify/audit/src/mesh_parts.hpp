// A triangle mesh's primitives for the audit: its edges, and which triangle owns each vertex
// and each edge (the lowest-numbered triangle holding it), so that a leaf pair of the tree
// generates each vertex-face and edge-edge pair exactly once (the owner's leaf against the
// other primitive's). Vertices in no triangle are owned by none: they are not part of the
// surface, and the audit does not test them.
#pragma once

#include <array>
#include <vector>

#include "fdh/bvh.hpp"

namespace fdh::audit {

using Edge = std::array<int, 2>;

struct MeshParts {
  std::vector<Tri> tris;
  std::vector<Edge> edges;  // each undirected edge once, ends in increasing order
  // What triangle t owns: vertices [vertex_start[t], vertex_start[t + 1]) of owned_vertices,
  // edges likewise.
  std::vector<int> vertex_start, owned_vertices, edge_start, owned_edges;
  // Per triangle: every edge of it has at most two triangles, which run it in opposite
  // directions (an oriented manifold there). Only nodes made of such triangles can be flat.
  std::vector<char> oriented;

  const int* vertices_begin(int t) const { return owned_vertices.data() + vertex_start[t]; }
  const int* vertices_end(int t) const { return owned_vertices.data() + vertex_start[t + 1]; }
  const int* edges_begin(int t) const { return owned_edges.data() + edge_start[t]; }
  const int* edges_end(int t) const { return owned_edges.data() + edge_start[t + 1]; }
};

// Throws std::invalid_argument naming the triangle on an index outside [0, vertices) or a
// repeated index.
MeshParts mesh_parts(int vertices, std::vector<Tri> tris, const char* what);

inline bool shares_vertex(const Tri& a, const Tri& b) {
  for (const int i : a)
    if (i == b[0] || i == b[1] || i == b[2]) return true;
  return false;
}

}  // namespace fdh::audit
