#include "audit_meshes.hpp"

#include <algorithm>
#include <set>

#include "fdh/ccd/robust.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/triangle_triangle.hpp"

namespace fdh::audit::testing {

Mesh grid(int n, double spacing, const Vec3& origin) {
  Mesh m;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) m.x.push_back(origin + Vec3{c * spacing, r * spacing, 0});
  for (int r = 0; r + 1 < n; ++r)
    for (int c = 0; c + 1 < n; ++c) {
      const int a = r * n + c, b = a + 1, d = a + n, e = d + 1;
      m.tris.push_back({a, b, e});
      m.tris.push_back({a, e, d});
    }
  return m;
}

Topology cloth_only(const Mesh& m) {
  Topology t;
  t.cloth_vertices = int(m.x.size());
  t.cloth = m.tris;
  return t;
}

Mesh join(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const int n = int(a.x.size());
  m.x.insert(m.x.end(), b.x.begin(), b.x.end());
  for (const Tri& t : b.tris) m.tris.push_back({t[0] + n, t[1] + n, t[2] + n});
  return m;
}

namespace {

std::vector<std::array<int, 2>> edges_of(const std::vector<Tri>& tris) {
  std::set<std::array<int, 2>> e;
  for (const Tri& t : tris)
    for (int c = 0; c < 3; ++c)
      e.insert({std::min(t[c], t[(c + 1) % 3]), std::max(t[c], t[(c + 1) % 3])});
  return {e.begin(), e.end()};
}

std::vector<int> vertices_of(const std::vector<Tri>& tris) {
  std::set<int> v;
  for (const Tri& t : tris) v.insert(t.begin(), t.end());
  return {v.begin(), v.end()};
}

// The moving query over four ids, the first `split` from (a0, a1), the rest from (b0, b1).
Query make(QueryKind kind, const std::array<int, 4>& ids, int split, const std::vector<Vec3>& a0,
           const std::vector<Vec3>& a1, const std::vector<Vec3>& b0, const std::vector<Vec3>& b1) {
  Query q;
  q.kind = kind;
  for (int i = 0; i < 4; ++i) {
    q.x[i] = i < split ? a0[ids[i]] : b0[ids[i]];
    q.x[i + 4] = i < split ? a1[ids[i]] : b1[ids[i]];
  }
  return q;
}

void add_if_hit(std::vector<Violation>& out, ViolationKind kind, const std::array<int, 4>& ids,
                int tri, const Query& q, int frame) {
  if (!exact::ccd_hit(q)) return;
  Violation v;
  v.kind = kind;
  v.frame = frame - 1;
  v.vertices = ids;
  v.triangle = tri;
  v.query = q;
  v.toi = robust_ccd_toi(q, kDefaultToiWidth, exact::ccd_toi);
  out.push_back(v);
}

bool shares(const Tri& a, const Tri& b) {
  for (const int i : a)
    if (i == b[0] || i == b[1] || i == b[2]) return true;
  return false;
}

// Vertices of mesh A (ids from va) against triangles of mesh B: every pair not sharing a vertex.
void vertex_face(const std::vector<int>& va, const std::vector<Tri>& tb, bool same_mesh, int split,
                 const std::vector<Vec3>& a0, const std::vector<Vec3>& a1,
                 const std::vector<Vec3>& b0, const std::vector<Vec3>& b1, ViolationKind kind,
                 int frame, std::vector<Violation>& out) {
  for (const int v : va)
    for (int t = 0; t < int(tb.size()); ++t) {
      const Tri& f = tb[t];
      if (same_mesh && (v == f[0] || v == f[1] || v == f[2])) continue;
      const std::array<int, 4> ids{v, f[0], f[1], f[2]};
      add_if_hit(out, kind, ids, t, make(QueryKind::VertexFace, ids, split, a0, a1, b0, b1), frame);
    }
}

}  // namespace

std::vector<Violation> brute_force(const Topology& topology, const std::vector<Vec3>& x0,
                                   const std::vector<Vec3>& x1, const std::vector<Vec3>& y0,
                                   const std::vector<Vec3>& y1, int frame, bool step) {
  std::vector<Violation> out;
  const auto& ct = topology.cloth;
  const auto& ot = topology.obstacle;
  if (step) {
    vertex_face(vertices_of(ct), ct, true, 1, x0, x1, x0, x1, ViolationKind::SelfVertexFace, frame,
                out);
    vertex_face(vertices_of(ct), ot, false, 1, x0, x1, y0, y1, ViolationKind::ClothVertexObstacle,
                frame, out);
    vertex_face(vertices_of(ot), ct, false, 1, y0, y1, x0, x1, ViolationKind::ObstacleVertexCloth,
                frame, out);
    const auto ce = edges_of(ct), oe = edges_of(ot);
    for (std::size_t i = 0; i < ce.size(); ++i) {
      for (std::size_t j = i + 1; j < ce.size(); ++j) {
        const auto &a = ce[i], &b = ce[j];
        if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
        const std::array<int, 4> ids{a[0], a[1], b[0], b[1]};
        add_if_hit(out, ViolationKind::SelfEdgeEdge, ids, -1,
                   make(QueryKind::EdgeEdge, ids, 4, x0, x1, x0, x1), frame);
      }
      for (const auto& b : oe) {
        const std::array<int, 4> ids{ce[i][0], ce[i][1], b[0], b[1]};
        add_if_hit(out, ViolationKind::ClothEdgeObstacleEdge, ids, -1,
                   make(QueryKind::EdgeEdge, ids, 2, x0, x1, y0, y1), frame);
      }
    }
  }
  const auto corners = [](const std::vector<Vec3>& x, const Tri& t) {
    return std::array<Vec3, 3>{x[t[0]], x[t[1]], x[t[2]]};
  };
  for (int a = 0; a < int(ct.size()); ++a) {
    for (int b = a + 1; b < int(ct.size()); ++b)
      if (!shares(ct[a], ct[b]) &&
          exact::triangles_intersect(corners(x1, ct[a]), corners(x1, ct[b]))) {
        Violation v;
        v.kind = ViolationKind::SelfIntersection;
        v.frame = frame;
        v.triangles = {a, b};
        out.push_back(v);
      }
    for (int o = 0; o < int(ot.size()); ++o)
      if (exact::triangles_intersect(corners(x1, ct[a]), corners(y1, ot[o]))) {
        Violation v;
        v.kind = ViolationKind::ObstacleIntersection;
        v.frame = frame;
        v.triangles = {a, o};
        out.push_back(v);
      }
  }
  return out;
}

}  // namespace fdh::audit::testing
