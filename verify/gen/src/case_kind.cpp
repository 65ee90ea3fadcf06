#include "fdh/gen/case_kind.hpp"

namespace fdh::verify {

CaseKind case_kind_of(const Query& q) {
  if (q.kind == QueryKind::EdgeEdge) return CaseKind::EdgeEdge;
  return q.is_static_vf() ? CaseKind::Static : CaseKind::MovingVertexFace;
}

std::string to_string(CaseKind k) {
  switch (k) {
    case CaseKind::Static:
      return "static vertex-face";
    case CaseKind::MovingVertexFace:
      return "moving vertex-face";
    case CaseKind::EdgeEdge:
      break;
  }
  return "edge-edge";
}

unsigned collapsed_primitives(const Query& q) {
  unsigned bits = 0;
  for (int t = 0; t < 2; ++t) {
    const Vec3* p = &q.x[4 * t];  // the four points at time t
    if (q.kind == QueryKind::VertexFace) {
      if (p[1] == p[2] || p[2] == p[3] || p[3] == p[1]) bits |= 1u << t;
    } else {
      if (p[0] == p[1]) bits |= 1u << t;
      if (p[2] == p[3]) bits |= 4u << t;
    }
  }
  return bits;
}

bool keeps_kind(const Query& drawn, const Query& q) {
  return case_kind_of(q) == case_kind_of(drawn) &&
         (collapsed_primitives(q) & ~collapsed_primitives(drawn)) == 0;
}

}  // namespace fdh::verify
