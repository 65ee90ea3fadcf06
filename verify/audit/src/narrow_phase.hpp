// The audit's narrow phase: the primitive pairs of one leaf pair of the trees (cloth against
// cloth, or cloth against obstacle), filtered by their swept axis-aligned boxes and decided
// exactly: moving vertex-face and edge-edge by `robust` CCD with the exact fallback (and the
// certified time of impact of each contact), the frame's triangle pairs by the robust
// triangle-triangle test.
#pragma once

#include <cstdint>
#include <vector>

#include "fdh/audit/auditor.hpp"
#include "mesh_parts.hpp"
#include "near_pairs.hpp"
#include "nearest.hpp"

namespace fdh::audit {

struct Aabb {
  Vec3 lo, hi;
};

// What one pass over a step (or over frame 0 alone) sees.
struct Pass {
  bool ccd = true;   // false: the static check of the frame only (frame 0, or Options::steps off)
  bool self = true;  // the cloth against itself too (Options::self)
  int frame = 0;     // the frame the static check looks at (a step ends there)
  const std::vector<Vec3>*c0 = nullptr, *c1 = nullptr;  // the cloth at the step's ends
  const std::vector<Vec3>*o0 = nullptr, *o1 = nullptr;  // the obstacles'
  std::vector<Aabb> cbox, obox;  // each vertex's box over the step (exact: min and max)
  int keep = 0;
  double toi_width = kDefaultToiWidth;
  // The minimum distance D (Options::min_distance; 0: contact only) and the pairs near by
  // construction. With `record` (the first frame, Options::near_first_frame) the pass only
  // notes the pairs within D (c0 == c1: a step that does not move) in Part::recorded.
  double d = 0;
  const NearPairs* near = nullptr;
  bool record = false;
};

// The boxes of pass.cbox and pass.obox, on every core.
void vertex_boxes(Pass& pass);

// What one chunk of work found: its counts and its earliest violations (at most 2 keep).
struct Part {
  StepCounts step;
  long self_intersections = 0, obstacle_intersections = 0, static_candidates = 0;
  long self_proximity = 0, obstacle_proximity = 0;
  NearExcluded excluded;
  std::vector<std::uint64_t> recorded;  // Pass::record: the pairs within D (NearPairs::key)
  NearestCandidate nearest[2];          // the nearest triangle pairs looked at: self, obstacle
  std::vector<Violation> kept;
  void add(Violation v, int keep);
  void merge(Part& other, int keep);
};

// Violations in report order: a step's before a frame's, a step's by time of impact; ties by
// kind and primitives, so the order is total and the same for any thread count.
bool earlier(const Violation& a, const Violation& b);

// Every pair owned by cloth triangles a and b (a != b): a's owned vertices against b, b's
// against a, a's owned edges against b's; and the pair (a, b) itself at the frame.
void self_pair(const MeshParts& cloth, int a, int b, const Pass& pass, Part& part);

// Cloth triangle c against obstacle triangle o: c's vertices against o, o's vertices against
// c, c's edges against o's; and the pair at the frame.
void obstacle_pair(const MeshParts& cloth, const MeshParts& obstacle, int c, int o,
                   const Pass& pass, Part& part);

}  // namespace fdh::audit
