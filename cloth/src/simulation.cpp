#include "fdh/cloth/simulation.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fdh/bvh.hpp"
#include "fdh/cloth/parallel.hpp"

namespace fdh::cloth {

FrameTimes& FrameTimes::operator+=(const FrameTimes& o) {
  springs += o.springs, refit += o.refit, traversal += o.traversal;
  narrow += o.narrow, response += o.response, self += o.self;
  return *this;
}

// The trees behind a run-time k.
struct Simulation::BroadPhase {
  virtual ~BroadPhase() = default;
  virtual void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) = 0;
  virtual void pairs(std::vector<std::pair<int, int>>& out) = 0;
};

template <int K>
struct Simulation::BroadPhaseK : Simulation::BroadPhase {
  Bvh<K> cloth, obstacles;
  BottomUp order;  // the cloth tree's refit, on every core when it is large
  std::vector<std::vector<std::pair<int, int>>> parts;

  BroadPhaseK(const std::vector<Vec3>& x, const TriMesh& mesh)
      : cloth(point_prims(int(x.size())), x), obstacles(mesh.tris, mesh.x), order(cloth.nodes()) {}
  void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) override {
    const double w = Bvh<K>::widening(x0, x1);
    order.run([&](int i) { cloth.refit_node(i, x0, x1, w); });
  }
  void pairs(std::vector<std::pair<int, int>>& out) override {
    // Every slab at once (kdop.hpp's overlap()): measured faster than §3.1's y slab first,
    // whose early exit rarely fires on a cloth lying on the table (docs/performance.md).
    if (cloth.nodes().size() < kParallelNodes) return traverse(cloth, obstacles, out);
    const auto overlaps = [](const Kdop<K>& a, const Kdop<K>& b) { return overlap(a, b); };
    const auto work = frontier(cloth, obstacles, 64, overlaps);
    gather_chunks(int(work.size()), parts, out, [&](int c, std::vector<std::pair<int, int>>& part) {
      std::vector<std::pair<int, int>> stack = {work[c]};
      descend_pairs(cloth, obstacles, stack, part, overlaps);
    });
  }
};

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point& t) {
  const auto now = Clock::now();
  const double s = std::chrono::duration<double>(now - t).count();
  t = now;
  return s;
}

}  // namespace

Simulation::Simulation(const Scene& scene, PointTriangleTest narrow, int k, double dt,
                       CcdTest self_exact, ExactToi self_toi)
    : scene_(scene), cloth_(scene.cloth), narrow_(narrow), dt_(dt > 0 ? dt : scene.dt) {
  if (!narrow_) throw std::invalid_argument("no narrow-phase test");
  for (const Obstacle& o : scene.obstacles) mesh_.append(obstacle_mesh(o, scene.skin()));
  for (int t = 0; t < int(mesh_.tris.size()); ++t) normals_.push_back(unit_normal(mesh_, t));
  broad_ = with_k(k, [&](auto kc) -> std::unique_ptr<BroadPhase> {
    return std::make_unique<BroadPhaseK<decltype(kc)::value>>(cloth_.x(), mesh_);
  });
  if (scene.self_collision)
    self_pass_ = std::make_unique<SelfCollision>(cloth_, k, self_exact, self_toi,
                                                 SelfCollision::kRounds, scene.self_gap(), dt_);
}

Simulation::~Simulation() = default;

Query Simulation::query(const NarrowQuery& q) const {
  const Tri& t = mesh_.tris[q.triangle];
  Query r;
  r.x = {x0_[q.particle], mesh_.x[t[0]], mesh_.x[t[1]], mesh_.x[t[2]],
         x1_[q.particle], mesh_.x[t[0]], mesh_.x[t[1]], mesh_.x[t[2]]};
  return r;
}

void Simulation::step() {
  auto clock = Clock::now();
  cloth_.integrate(dt_, x1_);
  x0_.swap(cloth_.x());  // the step's start, without a copy; x() gets the end below
  times_.springs = seconds_since(clock);

  broad_->refit(x0_, x1_);
  times_.refit = seconds_since(clock);

  pairs_.clear();
  broad_->pairs(pairs_);
  times_.traversal = seconds_since(clock);

  const auto& tris = mesh_.tris;
  queries_.resize(pairs_.size());
  for_chunks(int(pairs_.size()), 4096, [&](int begin, int end) {
    for (int q = begin; q < end; ++q) {
      const auto [p, t] = pairs_[q];
      const Tri& tri = tris[t];
      queries_[q] = {p, t,
                     narrow_(x0_[p], x1_[p], mesh_.x[tri[0]], mesh_.x[tri[1]], mesh_.x[tri[2]])};
    }
  });
  times_.narrow = seconds_since(clock);

  // Response in query order: after the first hit a particle lies outside that plane, so a
  // second hit on the same flat face changes nothing.
  std::vector<Vec3>& x = cloth_.x();
  std::vector<Vec3>& v = cloth_.v();
  x = x1_;
  collisions_ = 0;
  for (const NarrowQuery& q : queries_) {
    if (!q.hit || cloth_.pinned(q.particle)) continue;
    ++collisions_;
    const Vec3& n = normals_[q.triangle];
    const double s = dot(x[q.particle] - mesh_.x[tris[q.triangle][0]], n);
    if (s < kSurfaceGap) x[q.particle] += (kSurfaceGap - s) * n;
    v[q.particle] = respond(v[q.particle], n, scene_.response);
  }
  times_.response = seconds_since(clock);

  if (self_pass_) self_ = self_pass_->resolve(x0_, x, v);
  times_.self = seconds_since(clock);

  ++frame_;
  const auto bounded = [](const Vec3& p) {
    return std::abs(p.x) <= kMaxMagnitude && std::abs(p.y) <= kMaxMagnitude &&
           std::abs(p.z) <= kMaxMagnitude;  // false for nan too
  };
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!bounded(x[i]) || !bounded(v[i]))
      throw Diverged("the cloth diverged at frame " + std::to_string(frame_) + ": particle " +
                     std::to_string(i) + "'s " + (bounded(x[i]) ? "velocity" : "position") +
                     " is not finite or beyond 1e30; lower dt, the stiffness or the damping "
                     "(docs/limits.md)");
}

}  // namespace fdh::cloth
