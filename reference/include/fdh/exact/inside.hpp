// `exact`: is a point strictly inside a closed triangle mesh? CGAL's Side_of_triangle_mesh (ray
// parity) with exact predicates on exactly the given doubles; a point on the surface is not
// inside. The audit engine counts the cloth particles inside each closed obstacle with it
// (verify/audit/src/inside_count.hpp): a cloth piece wholly inside an obstacle meets none of
// its triangles, so only this finds it.
#pragma once

#include <memory>

#include "fdh/mesh.hpp"
#include "fdh/vec3.hpp"

namespace fdh::exact {

// Is `m` a closed manifold mesh (every triangle can be added to a halfedge mesh, and no edge is
// on a border)? Only then has it an inside.
bool is_closed_manifold(const TriMesh& m);

class ClosedMesh {
 public:
  // Throws std::invalid_argument("not a closed manifold mesh") unless is_closed_manifold(m).
  explicit ClosedMesh(const TriMesh& m);
  ~ClosedMesh();
  ClosedMesh(ClosedMesh&&) noexcept;
  ClosedMesh& operator=(ClosedMesh&&) noexcept;

  bool strictly_inside(const Vec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fdh::exact
