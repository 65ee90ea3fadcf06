#include "fdh/audit/counts.hpp"

namespace fdh::audit {

void AuditCounts::add(const AuditCounts& c) {
  self_intersections += c.self_intersections;
  obstacle_intersections += c.obstacle_intersections;
  static_candidates += c.static_candidates;
  step.self_vertex_face += c.step.self_vertex_face;
  step.self_edge_edge += c.step.self_edge_edge;
  step.cloth_vertex_obstacle += c.step.cloth_vertex_obstacle;
  step.obstacle_vertex_cloth += c.step.obstacle_vertex_cloth;
  step.cloth_edge_obstacle_edge += c.step.cloth_edge_obstacle_edge;
  step.candidates += c.step.candidates;
}

AuditCounts counts_of(const FrameReport& r) {
  AuditCounts c;
  c.self_intersections = r.self_intersections;
  c.obstacle_intersections = r.obstacle_intersections;
  c.static_candidates = r.static_candidates;
  if (r.has_step) c.step = r.step;
  return c;
}

long count_of(const AuditCounts& c, ViolationKind k) {
  if (const auto counter = counter_of(k)) return c.step.*counter;
  return k == ViolationKind::SelfIntersection ? c.self_intersections : c.obstacle_intersections;
}

}  // namespace fdh::audit
