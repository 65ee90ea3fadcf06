// The kind of a case, as shrinking keeps it: a static vertex-face query (the triangle still), a
// moving vertex-face query (the triangle moves), or an edge-edge query; and which of its
// primitives are whole. A family draws one kind (a moving vertex-face family draws moving
// triangles), and a shrunk case keeps the kind of the case drawn and collapses no primitive the
// case drawn had whole: a moving family's failure that shrinks into a still triangle, or every
// family's into the all-zero query, would say less about the family than the failure found.
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

// The primitives of q whose points coincide exactly, one bit each: for vertex-face the triangle
// with two equal corners at t = 0 (bit 0) and at t = 1 (bit 1); for edge-edge edge a with equal
// ends at t = 0 and 1 (bits 0, 1), edge b (bits 2, 3). Exact: equal doubles.
unsigned collapsed_primitives(const Query& q);

// Whether a shrink step from the case drawn may give q: q is of the same kind, and every
// primitive collapsed in q was collapsed in the case drawn already.
bool keeps_kind(const Query& drawn, const Query& q);

}  // namespace fdh::verify
