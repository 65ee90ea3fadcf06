// What an exact audit of cloth frames counts: the one count type of `fdhcert audit`'s
// certificate and of the scene runs' audit (simulate, scenes, table1, Python), per frame or
// summed over frames.
#pragma once

#include "fdh/audit/auditor.hpp"

namespace fdh::audit {

struct AuditCounts {
  long self_intersections = 0, obstacle_intersections = 0;  // within the frames
  long self_proximity = 0, obstacle_proximity = 0;          // within D in the frames
  StepCounts step;                                          // during the steps
  NearExcluded excluded;       // proximity tests the near rule left out
  long static_candidates = 0;  // triangle pairs tested
  // Cloth vertices strictly inside a closed obstacle (FrameReport::inside), summed over the
  // frames: a count of particles, not of violations, so not in total().
  long inside = 0;
  long total() const {
    return self_intersections + obstacle_intersections + self_proximity + obstacle_proximity +
           step.total();
  }
  void add(const AuditCounts& c);
};

// One frame report's counts (its step's only when it has one).
AuditCounts counts_of(const FrameReport& r);

// The count of one kind.
long count_of(const AuditCounts& c, ViolationKind k);

}  // namespace fdh::audit
