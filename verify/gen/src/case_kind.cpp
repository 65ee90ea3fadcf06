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

}  // namespace fdh::verify
