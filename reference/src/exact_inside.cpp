#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <optional>
#include <stdexcept>

#include "fdh/exact/inside.hpp"

namespace fdh::exact {
namespace {

// Epick: its predicates are exact (filtered, then exact arithmetic), and point location by ray
// parity uses predicates only, on the input doubles.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

Point point(const Vec3& p) {
  return Point(p.x, p.y, p.z);
}

// The halfedge mesh of m, or none when a triangle cannot be added (a non-manifold edge or
// vertex, or a triangle wound against its neighbour) or an edge is on a border.
std::optional<Mesh> closed_mesh(const TriMesh& m) {
  Mesh sm;
  std::vector<Mesh::Vertex_index> v;
  v.reserve(m.x.size());
  for (const Vec3& p : m.x) v.push_back(sm.add_vertex(point(p)));
  for (const Tri& t : m.tris)
    if (sm.add_face(v[t[0]], v[t[1]], v[t[2]]) == Mesh::null_face()) return std::nullopt;
  if (m.tris.empty() || !CGAL::is_closed(sm)) return std::nullopt;
  return sm;
}

}  // namespace

bool is_closed_manifold(const TriMesh& m) {
  return closed_mesh(m).has_value();
}

struct ClosedMesh::Impl {
  Mesh mesh;  // Side_of_triangle_mesh keeps a reference: Impl does not move
  std::optional<CGAL::Side_of_triangle_mesh<Mesh, K>> side;
};

ClosedMesh::ClosedMesh(const TriMesh& m) : impl_(std::make_unique<Impl>()) {
  std::optional<Mesh> sm = closed_mesh(m);
  if (!sm) throw std::invalid_argument("not a closed manifold mesh");
  impl_->mesh = std::move(*sm);
  impl_->side.emplace(impl_->mesh);
}

ClosedMesh::~ClosedMesh() = default;
ClosedMesh::ClosedMesh(ClosedMesh&&) noexcept = default;
ClosedMesh& ClosedMesh::operator=(ClosedMesh&&) noexcept = default;

bool ClosedMesh::strictly_inside(const Vec3& p) const {
  return (*impl_->side)(point(p)) == CGAL::ON_BOUNDED_SIDE;
}

}  // namespace fdh::exact
