#include "mesh_parts.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

namespace fdh::audit {
namespace {

void check_triangles(int vertices, const std::vector<Tri>& tris, const char* what) {
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const Tri& f = tris[t];
    for (const int i : f)
      if (i < 0 || i >= vertices)
        throw std::invalid_argument(std::string(what) + " triangle " + std::to_string(t) +
                                    ": vertex index " + std::to_string(i) + " is not in [0, " +
                                    std::to_string(vertices) + ")");
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
      throw std::invalid_argument(std::string(what) + " triangle " + std::to_string(t) +
                                  " repeats a vertex index");
  }
}

// Items 0 .. owner.size() - 1 grouped by their owner (-1: none), in index order: a CSR table.
void group(const std::vector<int>& owner, int owners, std::vector<int>& start,
           std::vector<int>& items) {
  start.assign(owners + 1, 0);
  for (const int o : owner)
    if (o >= 0) ++start[o + 1];
  for (int o = 0; o < owners; ++o) start[o + 1] += start[o];
  items.resize(start[owners]);
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int i = 0; i < int(owner.size()); ++i)
    if (owner[i] >= 0) items[next[owner[i]]++] = i;
}

}  // namespace

MeshParts mesh_parts(int vertices, std::vector<Tri> tris, const char* what) {
  check_triangles(vertices, tris, what);
  MeshParts m;
  m.tris = std::move(tris);
  const int n = int(m.tris.size());
  // Every directed edge with its triangle, sorted by undirected edge, then triangle.
  struct Use {
    int lo, hi, tri;
    bool forward;  // the triangle runs it lo -> hi
  };
  std::vector<Use> uses;
  uses.reserve(3 * std::size_t(n));
  for (int t = 0; t < n; ++t)
    for (int c = 0; c < 3; ++c) {
      const int a = m.tris[t][c], b = m.tris[t][(c + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return std::tie(x.lo, x.hi, x.tri) < std::tie(y.lo, y.hi, y.tri);
  });
  m.oriented.assign(n, 1);
  std::vector<int> edge_owner;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    const bool ok = j - i == 1 || (j - i == 2 && uses[i].forward != uses[i + 1].forward);
    if (!ok)
      for (std::size_t k = i; k < j; ++k) m.oriented[uses[k].tri] = 0;
    m.edges.push_back({uses[i].lo, uses[i].hi});
    edge_owner.push_back(uses[i].tri);  // the lowest-numbered triangle: sorted by tri
    i = j;
  }
  std::vector<int> vertex_owner(vertices, -1);
  for (int t = n - 1; t >= 0; --t)
    for (const int v : m.tris[t]) vertex_owner[v] = t;
  group(vertex_owner, n, m.vertex_start, m.owned_vertices);
  group(edge_owner, n, m.edge_start, m.owned_edges);
  return m;
}

}  // namespace fdh::audit
