#include "trees.hpp"

#include <algorithm>

#include "fdh/bvh.hpp"
#include "fdh/normal_cone.hpp"
#include "fdh/parallel/bottom_up.hpp"
#include "fdh/parallel/chunks.hpp"
#include "kernel_centre.hpp"
#include "patch_boundaries.hpp"

namespace fdh::audit {
namespace {

// A node's axis-aligned boxes at each end of the step (merged exactly: min and max).
struct Ends {
  Aabb at0, at1;
};
inline Aabb box_of(const Tri& t, const std::vector<Vec3>& x) {
  const Vec3 &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
  return {{min_of(a.x, b.x, c.x), min_of(a.y, b.y, c.y), min_of(a.z, b.z, c.z)},
          {max_of(a.x, b.x, c.x), max_of(a.y, b.y, c.y), max_of(a.z, b.z, c.z)}};
}
inline Aabb joined(const Aabb& a, const Aabb& b) {
  return {{min_of(a.lo.x, b.lo.x), min_of(a.lo.y, b.lo.y), min_of(a.lo.z, b.lo.z)},
          {max_of(a.hi.x, b.hi.x), max_of(a.hi.y, b.hi.y), max_of(a.hi.z, b.hi.z)}};
}
// Apart along an axis by more than d at both ends, the same way round: nothing under one node
// comes within d of anything under the other during the step (narrow_phase.cpp's
// apart_all_step, for whole subtrees; exact as it is).
inline bool apart_all_step(const Ends& a, const Ends& b, double d) {
  for (int i = 0; i < 3; ++i)
    if ((a.at0.lo[i] - b.at0.hi[i] > d && a.at1.lo[i] - b.at1.hi[i] > d) ||
        (b.at0.lo[i] - a.at0.hi[i] > d && b.at1.lo[i] - a.at1.hi[i] > d))
      return true;
  return false;
}

// The k-DOPs' overlap grown by d: two points within distance d project within |n| d of each
// other on a slab's direction n (|n| = 1 on the axes, sqrt 2 or sqrt 3 on the diagonals, both
// below 2), so boxes apart by more than that on a slab hold no pair within d. A difference that
// rounds above the margin is above it exactly (rounding is monotonic). d = 0: kdop.hpp's own.
template <int K>
bool overlap_within(const Kdop<K>& a, const Kdop<K>& b, double d) {
  if (d <= 0) return overlap(a, b);
  for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
    const double m = Kdop<K>::is_exact_slab(s) ? d : 2 * d;
    if (b.lo[s] - a.hi[s] > m || a.lo[s] - b.hi[s] > m) return false;
  }
  return true;
}

// A task: two nodes whose leaf pairs are to be found, cloth with cloth or cloth with obstacle.
struct Task {
  int a, b;
  bool obstacle;
};

// The positions a tree is built over: the first frame under a tiny generic shear. The tree's
// median splits order triangles by their centres along a direction, and on a regular grid whole
// rows of centres tie along every axis and diagonal; nth_element then cuts among the ties at
// random, and the nodes become scattered sets of triangles whose boundary is never one loop, so
// the normal cones cull nothing. The shear orders the ties by a second linear key, so the cuts
// are straight lines and the nodes patches. It moves a point by at most 1e-3 of the mean edge
// length (distinct keys keep their order) and by far more than a rounding. Only the tree's shape
// depends on it: every pass refits the boxes from the true positions first.
std::vector<Vec3> tie_broken(const std::vector<Tri>& tris, const std::vector<Vec3>& x) {
  double edges = 0, extent = 0;
  for (const Tri& t : tris) edges += norm(x[t[1]] - x[t[0]]);
  for (const Vec3& p : x) extent = std::max(extent, max_abs(p - x[0]));
  if (tris.empty() || edges == 0 || extent == 0) return x;
  const double eta = 1e-3 * edges / double(tris.size()) / extent;
  std::vector<Vec3> y(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 p = x[i] - x[0];
    y[i] = x[i] + eta * Vec3{0.7548776662 * p.y + 0.5698402910 * p.z,
                             0.3247179572 * p.x + 0.8191725134 * p.z,
                             0.6180339887 * p.x + 0.4142135624 * p.y};
  }
  return y;
}

// Chunks of work: about this many, whatever the thread count (results depend on sizes alone).
constexpr std::size_t kChunks = 2048;

// The FDH tree over tris at x, its subtrees built on every core (the same tree as one core's),
// unless it is small (parallel::kParallelNodes).
template <int K>
Bvh<K> tree(const std::vector<Tri>& tris, const std::vector<Vec3>& x) {
  parallel::Chunking how;
  how.parallel = 2 * tris.size() >= parallel::kParallelNodes;
  return Bvh<K>(tris, tie_broken(tris, x), {}, 1, [&](int n, const auto& f) {
    parallel::for_each_index(
        std::size_t(n), 1, [&](std::size_t i) { f(int(i)); }, how);
  });
}

}  // namespace

template <int K>
class TreesK : public Trees {
 public:
  TreesK(const MeshParts& cloth, const MeshParts& obstacle, const std::vector<Vec3>& x,
         const std::vector<Vec3>& y)
      : cloth_(cloth),
        obstacle_(obstacle),
        ctree_(tree<K>(cloth.tris, x)),
        otree_(tree<K>(obstacle.tris, y)) {
    const auto& nodes = ctree_.nodes();
    std::vector<NodeShape> shape(nodes.size());
    ends_.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto& n = nodes[i];
      shape[i] = n.leaf() ? NodeShape{-1, -1, ctree_.prims()[n.first]} : NodeShape{n.left, n.right};
      ends_[i] = parallel::subtree_end(nodes, int(i));
    }
    partner_ = cell_partners(cloth, x);
    loops_ = PatchBoundaries(shape, cloth, partner_);
    csub_ = parallel::BottomUp(nodes);
    osub_ = parallel::BottomUp(otree_.nodes());
    normals_.resize(nodes.size());
    lean_.resize(nodes.size());
  }

  std::vector<Part> run(const Pass& pass) override {
    const std::vector<Vec3> none;
    const bool moves = pass.ccd && *pass.c0 != *pass.c1;
    update(ctree_, csub_, *pass.c0, moves ? *pass.c1 : none, cends_, true);
    const bool obstacle_moves = pass.ccd && *pass.o0 != *pass.o1;
    update(otree_, osub_, *pass.o0, obstacle_moves ? *pass.o1 : none, oends_, false);
    const std::vector<Vec3>& x1 = moves ? *pass.c1 : *pass.c0;
    d_ = pass.d;
    std::vector<Task> tasks;
    if (pass.self) tasks = self_tasks(*pass.c0, x1);
    const double d = d_;
    for (const auto& [a, b] : frontier(ctree_, otree_, 256, [d](const Kdop<K>&p, const Kdop<K>&q) {
           return overlap_within(p, q, d);
         }))
      tasks.push_back({a, b, true});
    const std::size_t grain = std::max<std::size_t>(1, (tasks.size() + kChunks - 1) / kChunks);
    return parallel::parts_in_order(tasks.size(), grain, Part{},
                                    [&](std::size_t begin, std::size_t end, Part& part) {
                                      for (std::size_t i = begin; i < end; ++i)
                                        descend(tasks[i], pass, part);
                                    });
  }

  long flat_nodes() const override { return flat_count_; }

 private:
  // Refit, swept over x0 -> x1 (x1 empty: still at x0), with the cloth's normal boxes.
  void update(Bvh<K>& t, const parallel::BottomUp& sub, const std::vector<Vec3>& x0,
              const std::vector<Vec3>& x1, std::vector<Ends>& ends, bool normals) {
    if (t.empty()) return;
    const double w = Bvh<K>::widening(x0, x1);
    const std::vector<Vec3>& y1 = x1.empty() ? x0 : x1;
    const auto& nodes = t.nodes();
    ends.resize(nodes.size());
    sub.run([&](int i) {
      t.refit_node(i, x0, x1, w);
      const auto& n = nodes[i];
      if (n.leaf()) {
        const Tri& f = t.tris()[t.prims()[n.first]];
        ends[i] = {box_of(f, x0), box_of(f, y1)};
      } else {
        ends[i] = {joined(ends[n.left].at0, ends[n.right].at0),
                   joined(ends[n.left].at1, ends[n.right].at1)};
      }
      if (!normals) return;
      if (!n.leaf()) {
        normals_[i] = merge(normals_[n.left], normals_[n.right]);
        lean_[i] = lean_[n.left] + lean_[n.right];
        return;
      }
      // The leaf's triangle and its cell partner: flat() tests cell completions.
      const int tri = t.prims()[n.first];
      const auto swept = [&](const Tri& f) {
        return swept_normals(x0[f[1]] - x0[f[0]], y1[f[1]] - y1[f[0]], x0[f[2]] - x0[f[0]],
                             y1[f[2]] - y1[f[0]]);
      };
      normals_[i] = swept(t.tris()[tri]);
      if (partner_[tri] >= 0) normals_[i] = merge(normals_[i], swept(t.tris()[partner_[tri]]));
      lean_[i] = normals_[i].lo + normals_[i].hi;  // a direction inside the box, to aim at
    });
  }

  // Whether the node's patch cannot touch itself during the step (normal_cone.hpp): its
  // normals lean one way and its one boundary loop is star-shaped around a moving centre.
  // Not within a minimum distance: a patch that cannot touch itself can still come within D of
  // itself (a tight fold), so with D > 0 no node is flat.
  bool flat(int node, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) const {
    if (d_ > 0 || !loops_.has_loop(node)) return false;
    const int bit = best_direction(positive_directions(normals_[node]), lean_[node]);
    if (bit < 0) return false;
    thread_local std::vector<int> contour;
    contour.assign(loops_.begin(node), loops_.end(node));
    // The centre: inside the projected loop's kernel at each end of the step (any moving
    // centre is sound; this one passes where the patch is star-shaped at all).
    const Vec3 m0 = kernel_centre(contour, x0, bit);
    const Vec3 m1 = &x1 == &x0 ? m0 : kernel_centre(contour, x1, bit);
    return contour_is_star_shaped(contour, x0, x1, m0, m1, bit);
  }

  // Top down from `node`: a flat node needs nothing, a leaf (one triangle) nothing either;
  // otherwise its children's pair and what is below them. Nodes at `stop_depth` are left in
  // `deeper` for a pass of their own.
  void collect(int node, int depth, int stop_depth, const std::vector<Vec3>& x0,
               const std::vector<Vec3>& x1, std::vector<Task>& out, std::vector<int>* deeper,
               long& flats) const {
    const auto& n = ctree_.nodes()[node];
    if (n.leaf()) return;
    if (depth == stop_depth && deeper) {
      deeper->push_back(node);
      return;
    }
    if (flat(node, x0, x1)) {
      ++flats;
      return;
    }
    collect(n.left, depth + 1, stop_depth, x0, x1, out, deeper, flats);
    collect(n.right, depth + 1, stop_depth, x0, x1, out, deeper, flats);
    split(n.left, n.right, out);
  }

  // The cloth's sibling pairs to descend: the top of the tree on this thread, the subtrees
  // below depth 6 on every core, joined in order.
  std::vector<Task> self_tasks(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
    std::vector<Task> tasks;
    flat_count_ = 0;
    if (ctree_.empty()) return tasks;
    std::vector<int> deeper;
    collect(0, 0, 6, x0, x1, tasks, &deeper, flat_count_);
    struct Found {
      std::vector<Task> tasks;
      long flats = 0;
    };
    std::vector<Found> found(deeper.size());
    parallel::for_each_index(deeper.size(), 1, [&](std::size_t r) {
      collect(deeper[r], 0, -1, x0, x1, found[r].tasks, nullptr, found[r].flats);
    });
    for (const Found& f : found) {
      tasks.insert(tasks.end(), f.tasks.begin(), f.tasks.end());
      flat_count_ += f.flats;
    }
    return tasks;
  }

  // A pair of disjoint cloth nodes as tasks: split (while their boxes meet) until each side is
  // small enough for one chunk, so that no chunk holds most of the work.
  void split(int a, int b, std::vector<Task>& out) const {
    const auto& nodes = ctree_.nodes();
    if (!overlap_within(nodes[a].box, nodes[b].box, d_)) return;
    const int limit = std::max<int>(64, int(nodes.size() / kChunks));
    std::pair<int, int> first, second;
    if (ends_[a] - a + ends_[b] - b > limit && split_pair(ctree_, ctree_, a, b, first, second)) {
      split(first.first, first.second, out);
      split(second.first, second.second, out);
      return;
    }
    out.push_back({a, b, false});
  }

  // Every leaf pair under a task whose boxes meet (the swept k-DOPs overlap, and the boxes at
  // the step's ends are not apart the same way round at both), through the narrow phase.
  void descend(const Task& task, const Pass& pass, Part& part) const {
    const Bvh<K>& b = task.obstacle ? otree_ : ctree_;
    const std::vector<Ends>& bends = task.obstacle ? oends_ : cends_;
    const auto* A = ctree_.nodes().data();
    const auto* B = b.nodes().data();
    thread_local std::vector<std::pair<int, int>> stack;
    stack.assign(1, {task.a, task.b});
    while (!stack.empty()) {
      const auto [i, j] = stack.back();
      stack.pop_back();
      if (!overlap_within(A[i].box, B[j].box, d_) || apart_all_step(cends_[i], bends[j], d_))
        continue;
      std::pair<int, int> first, second;
      if (split_pair(ctree_, b, i, j, first, second)) {
        stack.push_back(second);
        stack.push_back(first);
        continue;
      }
      const int p = ctree_.prims()[A[i].first], q = b.prims()[B[j].first];
      if (task.obstacle)
        obstacle_pair(cloth_, obstacle_, p, q, pass, part);
      else
        self_pair(cloth_, p, q, pass, part);
    }
  }

  const MeshParts& cloth_;
  const MeshParts& obstacle_;
  Bvh<K> ctree_, otree_;
  std::vector<int> ends_;     // per cloth node: one past its subtree
  std::vector<int> partner_;  // per cloth triangle: its cell's other one, or -1
  PatchBoundaries loops_;
  parallel::BottomUp csub_, osub_;   // the trees' refit passes
  std::vector<Ends> cends_, oends_;  // per node: its boxes at the step's ends
  std::vector<NormalBox> normals_;
  std::vector<Vec3> lean_;
  long flat_count_ = 0;
  double d_ = 0;  // the pass's minimum distance (Pass::d)
};

std::unique_ptr<Trees> make_trees(int k, const MeshParts& cloth, const MeshParts& obstacle,
                                  const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  return with_k(k, [&](auto kc) -> std::unique_ptr<Trees> {
    return std::make_unique<TreesK<decltype(kc)::value>>(cloth, obstacle, x, y);
  });
}

}  // namespace fdh::audit
