#include "fdh/audit/auditor.hpp"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "inside_count.hpp"
#include "mesh_parts.hpp"
#include "near_pairs.hpp"
#include "nearest.hpp"
#include "trees.hpp"

namespace fdh::audit {

const char* to_string(ViolationKind k) {
  switch (k) {
    case ViolationKind::SelfIntersection:
      return "self-intersection";
    case ViolationKind::ObstacleIntersection:
      return "obstacle-intersection";
    case ViolationKind::SelfVertexFace:
      return "self-vertex-face";
    case ViolationKind::SelfEdgeEdge:
      return "self-edge-edge";
    case ViolationKind::ClothVertexObstacle:
      return "cloth-vertex-obstacle";
    case ViolationKind::ObstacleVertexCloth:
      return "obstacle-vertex-cloth";
    case ViolationKind::ClothEdgeObstacleEdge:
      return "cloth-edge-obstacle-edge";
    case ViolationKind::SelfProximity:
      return "self-proximity";
    case ViolationKind::ObstacleProximity:
      return "obstacle-proximity";
    case ViolationKind::SelfVertexFaceProximity:
      return "self-vertex-face-proximity";
    case ViolationKind::SelfEdgeEdgeProximity:
      return "self-edge-edge-proximity";
    case ViolationKind::ClothVertexObstacleProximity:
      return "cloth-vertex-obstacle-proximity";
    case ViolationKind::ObstacleVertexClothProximity:
      return "obstacle-vertex-cloth-proximity";
    case ViolationKind::ClothEdgeObstacleEdgeProximity:
      return "cloth-edge-obstacle-edge-proximity";
  }
  return "?";
}

bool is_proximity(ViolationKind k) {
  return k >= ViolationKind::SelfProximity;
}

// The proximity kinds follow the contact kinds in the same order.
ViolationKind contact_kind(ViolationKind k) {
  if (!is_proximity(k)) return k;
  return ViolationKind(int(k) - int(ViolationKind::SelfProximity));
}

ViolationKind proximity_kind(ViolationKind k) {
  if (is_proximity(k)) return k;
  return ViolationKind(int(k) + int(ViolationKind::SelfProximity));
}

bool is_step(ViolationKind k) {
  const ViolationKind c = contact_kind(k);
  return c != ViolationKind::SelfIntersection && c != ViolationKind::ObstacleIntersection;
}

long StepCounts::*counter_of(ViolationKind k) {
  switch (k) {
    case ViolationKind::SelfVertexFace:
      return &StepCounts::self_vertex_face;
    case ViolationKind::SelfEdgeEdge:
      return &StepCounts::self_edge_edge;
    case ViolationKind::ClothVertexObstacle:
      return &StepCounts::cloth_vertex_obstacle;
    case ViolationKind::ObstacleVertexCloth:
      return &StepCounts::obstacle_vertex_cloth;
    case ViolationKind::ClothEdgeObstacleEdge:
      return &StepCounts::cloth_edge_obstacle_edge;
    case ViolationKind::SelfVertexFaceProximity:
      return &StepCounts::self_vertex_face_near;
    case ViolationKind::SelfEdgeEdgeProximity:
      return &StepCounts::self_edge_edge_near;
    case ViolationKind::ClothVertexObstacleProximity:
      return &StepCounts::cloth_vertex_obstacle_near;
    case ViolationKind::ObstacleVertexClothProximity:
      return &StepCounts::obstacle_vertex_cloth_near;
    case ViolationKind::ClothEdgeObstacleEdgeProximity:
      return &StepCounts::cloth_edge_obstacle_edge_near;
    default:
      return nullptr;
  }
}

struct Auditor::Impl {
  Topology topology;
  Options options;
  MeshParts cloth, obstacle;
  std::unique_ptr<Trees> trees;
  std::unique_ptr<InsideCount> inside;              // the cloth's particles in the closed obstacles
  NearPairs near;                                   // with Options::min_distance > 0
  std::vector<Vec3> cloth_before, obstacle_before;  // the previous frame
  int given = 0;                                    // frames given so far
  int first_frame = 0;                   // the number of the first (a part's, start_part)
  std::optional<tbb::task_arena> arena;  // with Options::threads > 0

  FrameReport frame(const std::vector<Vec3>& x, const std::vector<Vec3>& y);
};

namespace {

void check_positions(const std::vector<Vec3>& x, int count, const char* what) {
  if (int(x.size()) != count)
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(x.size()) +
                                " vertices given, the topology has " + std::to_string(count));
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i].x) || !std::isfinite(x[i].y) || !std::isfinite(x[i].z))
      throw std::invalid_argument(std::string(what) + " vertex " + std::to_string(i) +
                                  ": a coordinate is not finite");
}

}  // namespace

Auditor::Auditor(Topology topology, Options options) : impl_(std::make_unique<Impl>()) {
  if (!is_valid_k(options.k))
    throw std::invalid_argument("k must be 6, 14, 18 or 26, not " + std::to_string(options.k));
  if (options.threads < 0) throw std::invalid_argument("threads must be >= 0");
  if (!(options.toi_width >= kMinToiWidth && options.toi_width <= 1))
    throw std::invalid_argument("toi_width must be in [2^-52, 1]");
  if (topology.cloth_vertices < 0 || topology.obstacle_vertices < 0)
    throw std::invalid_argument("a vertex count is negative");
  if (!(options.min_distance >= 0 && std::isfinite(options.min_distance)))
    throw std::invalid_argument("min_distance must be a finite number >= 0");
  if (options.near_rings < 0) throw std::invalid_argument("near_rings must be >= 0");
  // Primitive indices go into NearPairs' keys (30 bits each).
  if (std::max<std::size_t>({std::size_t(topology.cloth_vertices),
                             std::size_t(topology.obstacle_vertices), 3 * topology.cloth.size(),
                             3 * topology.obstacle.size()}) >= (std::size_t(1) << 30))
    throw std::invalid_argument("more than 2^30 vertices, edges or triangles");
  impl_->cloth = mesh_parts(topology.cloth_vertices, topology.cloth, "cloth");
  impl_->obstacle = mesh_parts(topology.obstacle_vertices, topology.obstacle, "obstacle");
  impl_->inside = std::make_unique<InsideCount>(impl_->obstacle.tris);
  if (options.min_distance > 0)
    impl_->near = NearPairs(impl_->cloth, topology.cloth_vertices, options.near_rings);
  impl_->topology = std::move(topology);
  impl_->options = options;
  if (options.threads > 0) impl_->arena.emplace(options.threads);
}

Auditor::~Auditor() = default;

const Topology& Auditor::topology() const {
  return impl_->topology;
}

FrameReport Auditor::add_frame(const std::vector<Vec3>& cloth, const std::vector<Vec3>& obstacle) {
  check_positions(cloth, impl_->topology.cloth_vertices, "cloth");
  check_positions(obstacle, impl_->topology.obstacle_vertices, "obstacle");
  if (impl_->arena) return impl_->arena->execute([&] { return impl_->frame(cloth, obstacle); });
  return impl_->frame(cloth, obstacle);
}

void Auditor::start_part(int first_frame, const std::vector<Vec3>& cloth0,
                         const std::vector<Vec3>& obstacle0) {
  check_positions(cloth0, impl_->topology.cloth_vertices, "cloth");
  check_positions(obstacle0, impl_->topology.obstacle_vertices, "obstacle");
  if (impl_->given > 0 || first_frame < 0)
    throw std::invalid_argument("start_part: before the first frame, from a frame >= 0");
  Impl& m = *impl_;
  m.first_frame = first_frame;
  const auto build = [&] {
    m.trees = make_trees(m.options.k, m.cloth, m.obstacle, cloth0, obstacle0);
  };
  if (m.arena)
    m.arena->execute(build);
  else
    build();
}

// The frame's static check and, from the second frame on, the step into it: one pass of the
// trees, whose parts are merged in order.
FrameReport Auditor::Impl::frame(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  const auto start = std::chrono::steady_clock::now();
  FrameReport r;
  r.frame = first_frame + given;
  r.has_step = given > 0 && options.steps;
  Pass pass;
  pass.ccd = r.has_step;
  pass.self = options.self;
  pass.frame = r.frame;
  pass.c0 = r.has_step ? &cloth_before : &x;
  pass.c1 = &x;
  pass.o0 = r.has_step ? &obstacle_before : &y;
  pass.o1 = &y;
  pass.keep = options.keep;
  pass.toi_width = options.toi_width;
  pass.d = options.min_distance;
  pass.near = &near;
  // The first frame with the near rule's first-frame part: a pass that does not move, noting
  // the pairs within D (and counting what a frame counts).
  pass.record = r.frame == 0 && pass.d > 0 && options.near_first_frame;
  pass.ccd = pass.ccd || pass.record;
  if (!trees) trees = make_trees(options.k, cloth, obstacle, x, y);
  if (pass.ccd) vertex_boxes(pass);
  std::vector<Part> parts = trees->run(pass);
  Part all;
  for (Part& p : parts) all.merge(p, options.keep);
  std::sort(all.kept.begin(), all.kept.end(), earlier);
  if (int(all.kept.size()) > options.keep) all.kept.resize(std::max(0, options.keep));
  r.self_intersections = all.self_intersections;
  r.obstacle_intersections = all.obstacle_intersections;
  r.static_candidates = all.static_candidates;
  r.self_proximity = all.self_proximity, r.obstacle_proximity = all.obstacle_proximity;
  r.excluded = all.excluded;
  if (pass.record) {
    near.set_first_frame(std::move(all.recorded));
    r.excluded.first_frame_pairs = near.first_frame_pairs();
  }
  if (pass.d > 0)
    for (int i = 0; i < 2; ++i) r.nearest[i] = nearest_of(all.nearest[i], r.frame, topology, x, y);
  r.step = all.step;
  r.inside = inside->count(x, cloth.owned_vertices, y);
  r.violations = std::move(all.kept);
  cloth_before = x;
  obstacle_before = y;
  ++given;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace fdh::audit
