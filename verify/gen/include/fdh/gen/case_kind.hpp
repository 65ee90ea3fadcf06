// The kind of a case, as shrinking keeps it: a static vertex-face query (the triangle still), a
// moving vertex-face query (the triangle moves), or an edge-edge query. A family draws one kind
// (a moving vertex-face family draws moving triangles), and a shrunk case keeps the kind of the
// case drawn: a moving family's failure that shrinks into a still triangle, or into the all-zero
// query of another family, would say less about the family than the failure found.
#pragma once

#include <string>

#include "fdh/query.hpp"

namespace fdh::verify {

enum class CaseKind { Static, MovingVertexFace, EdgeEdge };

// Edge-edge by q.kind; a vertex-face query is static when its triangle stands still
// (Query::is_static_vf), however its vertex moves.
CaseKind case_kind_of(const Query& q);

// "static vertex-face", "moving vertex-face", "edge-edge": as classify counts them.
std::string to_string(CaseKind k);

}  // namespace fdh::verify
