#include "fdh/audit/counts.hpp"

namespace fdh::audit {

void AuditCounts::add(const AuditCounts& c) {
  self_intersections += c.self_intersections;
  obstacle_intersections += c.obstacle_intersections;
  static_candidates += c.static_candidates;
  inside += c.inside;
  step.add(c.step);
}

AuditCounts counts_of(const FrameReport& r) {
  AuditCounts c;
  c.self_intersections = r.self_intersections;
  c.obstacle_intersections = r.obstacle_intersections;
  c.static_candidates = r.static_candidates;
  c.inside = r.inside;
  if (r.has_step) c.step = r.step;
  return c;
}

long count_of(const AuditCounts& c, ViolationKind k) {
  if (const auto counter = counter_of(k)) return c.step.*counter;
  return k == ViolationKind::SelfIntersection ? c.self_intersections : c.obstacle_intersections;
}

}  // namespace fdh::audit
