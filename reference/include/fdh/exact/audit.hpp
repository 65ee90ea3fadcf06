// The exact audit of a cloth frame against its obstacles (CGAL, exact predicates on exactly the
// given doubles):
// - inside: cloth particles strictly inside a closed obstacle mesh (touching the surface is not
//   inside);
// - crossing: cloth edges that pass through an obstacle triangle, their ends strictly on
//   opposite sides of its plane (an edge that only touches the surface is not crossing).
// A correct collision pass keeps both at 0.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "fdh/mesh.hpp"
#include "fdh/vec3.hpp"

namespace fdh::exact {

struct AuditCounts {
  long inside = 0, crossing = 0;
  long self_crossing = 0;  // filled by self_crossings(), when asked for
  AuditCounts& operator+=(const AuditCounts& o) {
    inside += o.inside, crossing += o.crossing, self_crossing += o.self_crossing;
    return *this;
  }
};

// The cloth against itself: its edges that pass through one of its triangles sharing no
// particle with the edge, the edge's ends strictly on opposite sides of the triangle's plane.
// Zero-area triangles are skipped (nothing passes through them).
long self_crossings(const std::vector<Vec3>& x, const std::vector<std::array<int, 2>>& edges,
                    const std::vector<Tri>& tris);

class Audit {
 public:
  // Each obstacle must be a closed mesh; otherwise std::invalid_argument.
  explicit Audit(const std::vector<TriMesh>& obstacles);
  ~Audit();
  Audit(const Audit&) = delete;
  Audit& operator=(const Audit&) = delete;

  AuditCounts count(const std::vector<Vec3>& x, const std::vector<std::array<int, 2>>& edges) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fdh::exact
