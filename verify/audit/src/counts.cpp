#include "fdh/audit/counts.hpp"

namespace fdh::audit {

void AuditCounts::add(const AuditCounts& c) {
  self_intersections += c.self_intersections;
  obstacle_intersections += c.obstacle_intersections;
  self_proximity += c.self_proximity, obstacle_proximity += c.obstacle_proximity;
  excluded.add(c.excluded);
  static_candidates += c.static_candidates;
  inside += c.inside;
  step.add(c.step);
}

AuditCounts counts_of(const FrameReport& r) {
  AuditCounts c;
  c.self_intersections = r.self_intersections;
  c.obstacle_intersections = r.obstacle_intersections;
  c.self_proximity = r.self_proximity, c.obstacle_proximity = r.obstacle_proximity;
  c.excluded = r.excluded;
  c.static_candidates = r.static_candidates;
  c.inside = r.inside;
  if (r.has_step) c.step = r.step;
  return c;
}

long count_of(const AuditCounts& c, ViolationKind k) {
  if (const auto counter = counter_of(k)) return c.step.*counter;
  switch (k) {
    case ViolationKind::SelfIntersection:
      return c.self_intersections;
    case ViolationKind::SelfProximity:
      return c.self_proximity;
    case ViolationKind::ObstacleProximity:
      return c.obstacle_proximity;
    default:
      return c.obstacle_intersections;
  }
}

}  // namespace fdh::audit
