// `fdhcert audit`'s engine: decides exactly whether a sequence of triangle-mesh frames (a cloth
// and optional obstacles, same topology in every frame, every vertex moving linearly between
// consecutive frames) ever penetrates:
// - within a frame: two cloth triangles that share no vertex intersect, or a cloth triangle
//   intersects an obstacle triangle (exact static triangle-triangle, from the segment-triangle
//   decisions of `robust` with their exact fallback);
// - during a step: a vertex passes through a triangle or an edge through an edge (moving
//   vertex-face and edge-edge CCD, `robust` with its exact fallback), cloth against itself and
//   against the obstacles (cloth vertices against obstacle triangles, obstacle vertices against
//   cloth triangles, cloth edges against obstacle edges).
// With a minimum distance D (Options::min_distance, `audit --min-distance`), also every such
// pair that comes within distance D without meeting (the proximity kinds), but for the pairs
// near by construction (Options::near_rings, near_first_frame; near_pairs.hpp).
// Frames are given one at a time (two in memory), so a long sequence streams. The first frame
// also builds the trees (verify/audit/src/trees.hpp), which later frames refit.
// Touching counts as meeting, everywhere: this engine is the one place that decides it (a
// primitive that only touches another is a violation of each kind above), and every exact audit
// of cloth frames (`fdhcert audit`, the scene runs of simulate, scenes, table1 and Python) is
// this engine.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/ccd/toi.hpp"
#include "fdh/query.hpp"
#include "fdh/vec3.hpp"

namespace fdh::audit {

// The topology, fixed for the whole sequence. Indices count from 0 in file order. Vertices in no
// triangle are not part of a surface and are not tested.
struct Topology {
  int cloth_vertices = 0;
  std::vector<Tri> cloth;  // triangles, indices into the cloth's vertices
  int obstacle_vertices = 0;
  std::vector<Tri> obstacle;  // triangles, indices into the obstacles' vertices (may be empty)
};

enum class ViolationKind {
  SelfIntersection,       // frame: two cloth triangles sharing no vertex intersect
  ObstacleIntersection,   // frame: a cloth triangle intersects an obstacle triangle
  SelfVertexFace,         // step: a cloth vertex meets a cloth triangle not holding it
  SelfEdgeEdge,           // step: two cloth edges sharing no vertex meet
  ClothVertexObstacle,    // step: a cloth vertex meets an obstacle triangle
  ObstacleVertexCloth,    // step: an obstacle vertex meets a cloth triangle
  ClothEdgeObstacleEdge,  // step: a cloth edge meets an obstacle edge
  // Proximity (Options::min_distance D > 0 only): the pairs of the kinds above that come within
  // distance D (distance <= D) without meeting, each kept apart from its intersection kind.
  SelfProximity,                  // frame: two cloth triangles sharing no vertex
  ObstacleProximity,              // frame: a cloth triangle and an obstacle triangle
  SelfVertexFaceProximity,        // step: as SelfVertexFace, within D
  SelfEdgeEdgeProximity,          // step: as SelfEdgeEdge, within D
  ClothVertexObstacleProximity,   // step: as ClothVertexObstacle, within D
  ObstacleVertexClothProximity,   // step: as ObstacleVertexCloth, within D
  ClothEdgeObstacleEdgeProximity  // step: as ClothEdgeObstacleEdge, within D
};
const char* to_string(ViolationKind k);  // "self-intersection", "self-vertex-face", ...
bool is_step(ViolationKind k);           // a CCD contact during a step, not a frame's state
bool is_proximity(ViolationKind k);      // within D without meeting
// The intersection kind a proximity kind is kept apart from (the same primitives); k itself
// for an intersection kind.
ViolationKind contact_kind(ViolationKind k);
// The proximity kind of an intersection kind's primitives.
ViolationKind proximity_kind(ViolationKind k);

struct Violation {
  ViolationKind kind;
  // A frame's: the frame. A step's: the frame it starts from (the step from frame to frame + 1).
  int frame = 0;
  // The two primitives: triangles (frame kinds, cloth first, in `triangles`; `vertices` then
  // all -1; two cloth triangles: the lower index first), or for a step the query's four
  // vertices in fdh::Query's order (vertex-face: v f0 f1 f2; edge-edge: ea0 ea1 eb0 eb1), cloth
  // vertex indices as they are, obstacle vertex indices as they are (the kind says which is
  // which), and the triangle's index in `triangle` (vertex-face kinds; -1 otherwise).
  std::array<int, 4> vertices{-1, -1, -1, -1};
  int triangle = -1;
  std::array<int, 2> triangles{-1, -1};  // frame kinds: cloth triangle, other triangle
  // A step's: the query (replayable by `classify` / `replay`) and its certified time of impact
  // (robust_ccd_toi: t_lo <= t* <= t_hi, in step units); a proximity kind's query asks at
  // min_distance D, and its time is the certified earliest time within D. A frame's: the two
  // triangles at the frame as a static edge-triangle query (the first edge found through the
  // other triangle; for proximity, the first triangle's first corner against the other).
  Query query;
  Toi toi;
};

struct StepCounts {  // contacts during one step
  long self_vertex_face = 0, self_edge_edge = 0;
  long cloth_vertex_obstacle = 0, obstacle_vertex_cloth = 0, cloth_edge_obstacle_edge = 0;
  long candidates = 0;  // CCD queries run
  // Within D without contact (Options::min_distance > 0), by kind as above.
  long self_vertex_face_near = 0, self_edge_edge_near = 0, cloth_vertex_obstacle_near = 0,
       obstacle_vertex_cloth_near = 0, cloth_edge_obstacle_edge_near = 0;
  long total() const {
    return self_vertex_face + self_edge_edge + cloth_vertex_obstacle + obstacle_vertex_cloth +
           cloth_edge_obstacle_edge + self_vertex_face_near + self_edge_edge_near +
           cloth_vertex_obstacle_near + obstacle_vertex_cloth_near + cloth_edge_obstacle_edge_near;
  }
  void add(const StepCounts& o) {  // the one sum of two parts' or frames' step counts
    self_vertex_face += o.self_vertex_face, self_edge_edge += o.self_edge_edge;
    cloth_vertex_obstacle += o.cloth_vertex_obstacle;
    obstacle_vertex_cloth += o.obstacle_vertex_cloth;
    cloth_edge_obstacle_edge += o.cloth_edge_obstacle_edge, candidates += o.candidates;
    self_vertex_face_near += o.self_vertex_face_near, self_edge_edge_near += o.self_edge_edge_near;
    cloth_vertex_obstacle_near += o.cloth_vertex_obstacle_near;
    obstacle_vertex_cloth_near += o.obstacle_vertex_cloth_near;
    cloth_edge_obstacle_edge_near += o.cloth_edge_obstacle_edge_near;
  }
};

// A nearest pair of triangles seen in a frame (Options::min_distance > 0): among the pairs
// the proximity test looked at (their boxes within D, not excluded by the near rule), the one
// nearest by a floating-point estimate, with its distance exactly (fdh/exact/distance.hpp).
struct Nearest {
  ViolationKind kind = ViolationKind::SelfProximity;  // or ObstacleProximity
  int frame = -1;                                     // -1: no pair looked at
  std::array<int, 2> triangles{-1, -1};               // cloth triangle, other triangle
  std::string squared;                                // the exact squared distance, "p/q"
  double lo = 0, hi = 0;                              // lo <= distance <= hi
};

// What the rule on pairs near by construction left out of the proximity kinds (never out of
// the intersection kinds): pair tests, per frame and step.
struct NearExcluded {
  long rings = 0;        // cloth pairs within NearRule::rings rings of each other
  long first_frame = 0;  // pairs within D in the first frame
  // The distinct pairs found within D in the first frame (its report only; by kind as the
  // primitives are paired: triangle pairs, vertex-face, edge-edge).
  long first_frame_pairs = 0;
  void add(const NearExcluded& o) {
    rings += o.rings, first_frame += o.first_frame, first_frame_pairs += o.first_frame_pairs;
  }
};
// The counter of a step kind in StepCounts; nullptr for a frame kind (the one map from kinds to
// counters, for the engine and the certificate).
long StepCounts::*counter_of(ViolationKind k);

struct FrameReport {
  int frame = 0;
  long self_intersections = 0, obstacle_intersections = 0;  // within the frame
  long self_proximity = 0, obstacle_proximity = 0;          // within D in the frame
  long static_candidates = 0;                               // triangle pairs tested
  NearExcluded excluded;  // proximity tests left out by the near rule (frame and step)
  // With min_distance > 0: the nearest pair of the cloth against itself ([0]) and against the
  // obstacles ([1]).
  std::array<Nearest, 2> nearest;
  // Cloth vertices (those in a triangle) strictly inside a closed obstacle at the frame: each
  // connected piece of the obstacles that is a closed manifold mesh, exactly (ray parity,
  // fdh/exact/inside.hpp; on the surface is not inside); open pieces have no inside. A cloth
  // piece wholly inside an obstacle meets none of its triangles: only this count sees it.
  long inside = 0;
  bool has_step = false;  // frame > 0: `step` is the step from frame - 1 to this frame
  StepCounts step;
  double seconds = 0;  // wall time of this frame's checks (broad and narrow phase)
  // Up to Options::keep violations of this frame and of the step into it, earliest first (a
  // step's before the frame it ends in; within a step by t_lo).
  std::vector<Violation> violations;
};

struct Options {
  int k = 18;       // the FDH's k (6, 14, 18 or 26)
  int keep = 16;    // violations kept per frame report
  int threads = 0;  // 0: every core
  double toi_width = kDefaultToiWidth;
  // false: every frame is checked on its own, with no step between frames (the frames given are
  // far apart, e.g. a scene's every 100th, so a straight motion between them means nothing).
  bool steps = true;
  // false: the cloth only against the obstacles, not against itself.
  bool self = true;
  // The minimum distance D (`audit --min-distance`): > 0 adds the proximity kinds (closed
  // primitives at distance <= D, D at the double's exact value) and grows the broad phase by D;
  // 0: contact only, today's audit.
  double min_distance = 0;
  // Pairs near by construction, left out of the proximity kinds (docs/audit.md): cloth pairs
  // whose vertices are within `near_rings` edges of each other in the mesh (0: none beyond
  // those sharing a vertex), and with `near_first_frame` pairs already within D in the first
  // frame.
  int near_rings = 2;
  bool near_first_frame = true;
};

class Auditor {
 public:
  // Throws std::invalid_argument on a triangle with an index out of range or a repeated index.
  Auditor(Topology topology, Options options = {});
  ~Auditor();
  Auditor(const Auditor&) = delete;
  Auditor& operator=(const Auditor&) = delete;

  // The next frame: the cloth's positions (cloth_vertices of them) and the obstacles'
  // (obstacle_vertices; still obstacles pass the same positions every time). Checks the frame,
  // and from the second frame on the step from the previous one. Throws std::invalid_argument
  // on a wrong count or a coordinate that is not finite.
  FrameReport add_frame(const std::vector<Vec3>& cloth, const std::vector<Vec3>& obstacle);

  // A part of a longer sequence (`fdhcert audit --part`), before the first add_frame: frames are
  // numbered from `first_frame`, and the trees are built over the sequence's frame 0 (`cloth0`,
  // `obstacle0`) as the whole run builds them, so that the part counts the whole run's
  // candidates. Throws std::invalid_argument as add_frame does, or after a frame.
  void start_part(int first_frame, const std::vector<Vec3>& cloth0,
                  const std::vector<Vec3>& obstacle0);

  const Topology& topology() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fdh::audit
