#include "fdh/exact/audit.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <deque>
#include <stdexcept>
#include <string>

namespace fdh::exact {
namespace {

// Epick: predicates are exact (filtered, then exact arithmetic), and the audit only uses
// predicates on the input doubles: point location by ray parity, box tests, orientations.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

Point point(const Vec3& p) {
  return Point(p.x, p.y, p.z);
}

// Does segment pq pass through the closed triangle abc with p and q strictly on opposite sides
// of its plane? Then the segment meets the triangle iff it passes on the same side of (or on)
// the three lines of its edges.
bool passes_through(const Point& p, const Point& q, const Point& a, const Point& b,
                    const Point& c) {
  const CGAL::Orientation sp = CGAL::orientation(a, b, c, p), sq = CGAL::orientation(a, b, c, q);
  if (sp == CGAL::COPLANAR || sq == CGAL::COPLANAR || sp == sq) return false;
  const CGAL::Orientation e[3] = {CGAL::orientation(p, q, a, b), CGAL::orientation(p, q, b, c),
                                  CGAL::orientation(p, q, c, a)};
  bool negative = false, positive = false;
  for (const CGAL::Orientation o : e)
    negative |= o == CGAL::NEGATIVE, positive |= o == CGAL::POSITIVE;
  return !(negative && positive);
}

}  // namespace

struct Audit::Impl {
  std::deque<Mesh> meshes;  // Side_of_triangle_mesh keeps a reference: stable addresses
  std::deque<CGAL::Side_of_triangle_mesh<Mesh, K>> inside;
  Triangles triangles;
  Tree tree;
  CGAL::Bbox_3 box;
};

Audit::Audit(const std::vector<TriMesh>& obstacles) : impl_(std::make_unique<Impl>()) {
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    const TriMesh& m = obstacles[o];
    Mesh& sm = impl_->meshes.emplace_back();
    std::vector<Mesh::Vertex_index> v;
    for (const Vec3& p : m.x) v.push_back(sm.add_vertex(point(p)));
    bool ok = true;
    for (const Tri& t : m.tris) {
      ok = ok && sm.add_face(v[t[0]], v[t[1]], v[t[2]]) != Mesh::null_face();
      impl_->triangles.emplace_back(point(m.x[t[0]]), point(m.x[t[1]]), point(m.x[t[2]]));
    }
    if (!ok || !CGAL::is_closed(sm))
      throw std::invalid_argument("obstacle " + std::to_string(o + 1) +
                                  " is not a closed manifold mesh");
    impl_->inside.emplace_back(sm);
  }
  impl_->tree.rebuild(impl_->triangles.begin(), impl_->triangles.end());
  for (const auto& t : impl_->triangles) impl_->box += t.bbox();
}

Audit::~Audit() = default;

AuditCounts Audit::count(const std::vector<Vec3>& x,
                         const std::vector<std::array<int, 2>>& edges) const {
  AuditCounts c;
  if (impl_->triangles.empty()) return c;
  for (const Vec3& p : x) {
    const Point q = point(p);
    for (const auto& side : impl_->inside)
      if (side(q) == CGAL::ON_BOUNDED_SIDE) {
        ++c.inside;
        break;
      }
  }
  std::vector<Primitive::Id> near;
  for (const auto& [i, j] : edges) {
    const Point p = point(x[i]), q = point(x[j]);
    if (p == q) continue;
    const CGAL::Bbox_3 box = K::Segment_3(p, q).bbox();
    if (!CGAL::do_overlap(box, impl_->box)) continue;
    near.clear();
    impl_->tree.all_intersected_primitives(box, std::back_inserter(near));
    for (const auto& t : near)
      if (passes_through(p, q, t->vertex(0), t->vertex(1), t->vertex(2))) {
        ++c.crossing;
        break;
      }
  }
  return c;
}

long self_crossings(const std::vector<Vec3>& x, const std::vector<std::array<int, 2>>& edges,
                    const std::vector<Tri>& tris) {
  Triangles triangles;
  std::vector<int> index;  // triangles[i] is tris[index[i]]
  for (int t = 0; t < int(tris.size()); ++t) {
    const Point a = point(x[tris[t][0]]), b = point(x[tris[t][1]]), c = point(x[tris[t][2]]);
    if (CGAL::collinear(a, b, c)) continue;
    triangles.emplace_back(a, b, c);
    index.push_back(t);
  }
  if (triangles.empty()) return 0;
  const Tree tree(triangles.begin(), triangles.end());
  long crossing = 0;
  std::vector<Primitive::Id> near;
  for (const auto& [i, j] : edges) {
    const Point p = point(x[i]), q = point(x[j]);
    if (p == q) continue;
    // Boxes first (a cloth edge's box meets its own neighbours' triangles): only triangles
    // sharing no particle with the edge get the exact tests.
    near.clear();
    tree.all_intersected_primitives(K::Segment_3(p, q).bbox(), std::back_inserter(near));
    for (const auto& h : near) {
      const Tri& t = tris[index[h - triangles.begin()]];
      if (t[0] == i || t[1] == i || t[2] == i || t[0] == j || t[1] == j || t[2] == j) continue;
      if (passes_through(p, q, h->vertex(0), h->vertex(1), h->vertex(2))) {
        ++crossing;
        break;
      }
    }
  }
  return crossing;
}

}  // namespace fdh::exact
