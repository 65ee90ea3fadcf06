#include "fdh/cloth/self_collision.hpp"

#include <stdexcept>
#include <string>

#include "fdh/bvh.hpp"

namespace fdh::cloth {

// The three trees behind a run-time k: particles, triangles and edges, all swept.
struct SelfCollision::Trees {
  virtual ~Trees() = default;
  virtual void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) = 0;
  virtual void vertex_face(std::vector<std::pair<int, int>>& out) const = 0;
  virtual void edge_edge(std::vector<std::pair<int, int>>& out) const = 0;
};

template <int K>
struct SelfCollision::TreesK : SelfCollision::Trees {
  Bvh<K> points, triangles, edges;
  TreesK(const Cloth& c)
      : points(point_prims(c.n()), c.x()),
        triangles(c.triangles(), c.x()),
        edges(as_edges(c.edges()), c.x()) {}
  static std::vector<Tri> as_edges(const std::vector<std::array<int, 2>>& e) {
    std::vector<Tri> t;
    for (const auto& [i, j] : e) t.push_back({i, j, j});
    return t;
  }
  void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) override {
    points.refit(x0, x1);
    triangles.refit(x0, x1);
    edges.refit(x0, x1);
  }
  void vertex_face(std::vector<std::pair<int, int>>& out) const override {
    traverse(points, triangles, out);
  }
  void edge_edge(std::vector<std::pair<int, int>>& out) const override {
    traverse_self(edges, out);
  }
};

SelfCollision::SelfCollision(const Cloth& cloth, int k, CcdTest exact) : exact_(exact) {
  if (!exact_) throw std::invalid_argument("self-collision needs an exact CCD fallback");
  trees_ = with_k(k, [&](auto kc) -> std::unique_ptr<Trees> {
    return std::make_unique<TreesK<decltype(kc)::value>>(cloth);
  });
}

SelfCollision::~SelfCollision() = default;

SelfCollision::Result SelfCollision::resolve(const Cloth& cloth, const std::vector<Vec3>& x0,
                                             std::vector<Vec3>& x, std::vector<Vec3>& v) {
  constexpr int kRounds = 4;
  Result r;
  const auto& tris = cloth.triangles();
  const auto& edges = cloth.edges();
  for (int round = 0; round <= kRounds; ++round) {
    trees_->refit(x0, x);
    stop_.assign(x.size(), 0);
    bool any = false;
    const auto test = [&](QueryKind kind, std::array<int, 4> ids) {
      Query q;
      q.kind = kind;
      for (int i = 0; i < 4; ++i) q.x[i] = x0[ids[i]], q.x[i + 4] = x[ids[i]];
      ++r.queries;
      if (!robust_ccd(q, exact_)) return;
      ++r.hits;
      any = true;
      for (const int i : ids) stop_[i] = 1;
    };
    pairs_.clear();
    trees_->vertex_face(pairs_);
    for (const auto& [p, t] : pairs_) {
      const Tri& f = tris[t];
      if (p == f[0] || p == f[1] || p == f[2]) continue;  // its own triangle
      test(QueryKind::VertexFace, {p, f[0], f[1], f[2]});
    }
    pairs_.clear();
    trees_->edge_edge(pairs_);
    for (const auto& [a, b] : pairs_) {
      const auto& ea = edges[a];
      const auto& eb = edges[b];
      if (ea[0] == eb[0] || ea[0] == eb[1] || ea[1] == eb[0] || ea[1] == eb[1]) continue;
      test(QueryKind::EdgeEdge, {ea[0], ea[1], eb[0], eb[1]});
    }
    if (!any) return r;
    if (round == kRounds) break;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (stop_[i]) x[i] = x0[i], v[i] = Vec3{};
  }
  // Still in contact after every round: the whole cloth stays where the step started.
  x = x0;
  for (Vec3& u : v) u = Vec3{};
  r.stopped_all = true;
  return r;
}

}  // namespace fdh::cloth
