// One cloth among still obstacles, stepped frame by frame. Each frame (one step of Δt):
//   1. springs and integration: eqs. (1)–(3) give every particle's end of step;
//   2. refit: the cloth's FDH tree over the particles, leaves swept from start to end (§2);
//   3. traversal: the cloth tree against the obstacles' tree (§3; each box test checks every
//      slab at once, which subsumes §3.1's y slab first);
//   4. narrow phase: the chosen point–triangle test on every candidate pair (§3.2);
//   5. response: for each hit, eqs. (4)–(5) on the velocity, and the particle put back on the
//      surface it crossed (a hair outside it, so that the next step starts outside);
//   6. self-collision, if the scene asks for it (fdh/cloth/self_collision.hpp).
// The obstacles collide through a skin: each is grown by the scene's thickness.
#pragma once

#include <memory>
#include <vector>

#include "fdh/cloth/cloth.hpp"
#include "fdh/cloth/scene.hpp"
#include "fdh/cloth/self_collision.hpp"
#include "fdh/point_triangle/robust.hpp"
#include "fdh/query.hpp"
#include "fdh/vec3.hpp"

namespace fdh::cloth {

// How far outside the crossed plane a particle is put back: 2^-30 m, far above the rounding of
// the projection (a few ulps of the coordinates) for scenes within 1 km of the origin.
inline constexpr double kSurfaceGap = 9.313225746154785e-10;

struct FrameTimes {  // seconds
  double springs = 0, refit = 0, traversal = 0, narrow = 0, response = 0, self = 0;
  double collision() const { return refit + traversal + narrow + response + self; }
  double total() const { return springs + collision(); }
  FrameTimes& operator+=(const FrameTimes& o);
};

struct NarrowQuery {
  int particle, triangle;
  bool hit;
};

class Simulation {
 public:
  // k: the FDH's k (6, 14, 18 or 26). dt <= 0 takes the scene's. self_exact, self_toi: the
  // exact CCD behind the self-collision pass's robust test and time of impact; required if the
  // scene asks for the pass.
  Simulation(const Scene& scene, PointTriangleTest narrow, int k = 18, double dt = 0,
             CcdTest self_exact = nullptr, ExactToi self_toi = nullptr);
  ~Simulation();

  // Throws Diverged (naming the frame and the particle) when a position or a velocity is no
  // longer finite or passes kMaxMagnitude.
  void step();

  const Scene& scene() const { return scene_; }
  const Cloth& cloth() const { return cloth_; }
  double dt() const { return dt_; }
  // The obstacles grown by the skin: what the narrow phase tests against.
  const TriMesh& collision_mesh() const { return mesh_; }

  // The last frame: its times, and its narrow-phase queries. Query q moved particle
  // q.particle from step_start() to step_end() against triangle q.triangle of collision_mesh().
  const FrameTimes& times() const { return times_; }
  const std::vector<NarrowQuery>& queries() const { return queries_; }
  int collisions() const { return collisions_; }
  const SelfCollision::Result& self() const { return self_; }
  const std::vector<Vec3>& step_start() const { return x0_; }
  const std::vector<Vec3>& step_end() const { return x1_; }
  // Query q as a static vertex-face query: the particle's path against the still triangle.
  Query query(const NarrowQuery& q) const;

 private:
  struct BroadPhase;
  template <int K>
  struct BroadPhaseK;

  Scene scene_;
  Cloth cloth_;
  PointTriangleTest narrow_;
  double dt_;
  TriMesh mesh_;
  std::vector<Vec3> normals_;
  std::unique_ptr<BroadPhase> broad_;
  std::unique_ptr<SelfCollision> self_pass_;
  SelfCollision::Result self_;
  std::vector<Vec3> x0_, x1_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<NarrowQuery> queries_;
  int collisions_ = 0;
  long frame_ = 0;
  FrameTimes times_;
};

}  // namespace fdh::cloth
