#include "fdh/cloth/self_collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "fdh/cloth/pair_distance.hpp"
#include "fdh/cloth/parallel.hpp"
#include "fdh/cloth/patch_tree.hpp"

namespace fdh::cloth {

using Candidate = SelfCollision::Candidate;

// The patch tree with a swept FDH per node, behind a run-time k.
struct SelfCollision::Trees {
  virtual ~Trees() = default;
  // The candidates of the step x0 -> x1, in an order fixed by the tree alone; with `changed`
  // (per particle; empty: all), only those with a changed particle, and patches without one are
  // not visited.
  virtual void candidates(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                          const std::vector<char>& changed, std::vector<Candidate>& out) = 0;
};

namespace {

// A particle's swept box on the three axes only: the primitive-level filter of cell_pairs,
// cheaper to merge than the full FDH and still conservative (a box containing the FDH).
struct Aabb {
  Vec3 lo, hi;
};
inline Aabb join(const Aabb& a, const Aabb& b) {
  return {{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y), std::min(a.lo.z, b.lo.z)},
          {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y), std::max(a.hi.z, b.hi.z)}};
}
inline bool meet(const Aabb& a, const Aabb& b) {
  return !(a.hi.x < b.lo.x || b.hi.x < a.lo.x || a.hi.y < b.lo.y || b.hi.y < a.lo.y ||
           a.hi.z < b.lo.z || b.hi.z < a.lo.z);
}

// Every pair of primitives, one owned by cell a and one by cell b (a == b: both in one cell),
// that shares no particle and whose swept boxes (merged from the particles' boxes) overlap.
void cell_pairs(const PatchTree& t, const Cloth& cloth, const std::vector<Aabb>& pbox, int a, int b,
                std::vector<Candidate>& out) {
  const auto& tris = cloth.triangles();
  const auto& edges = cloth.edges();
  const auto vf = [&](int from, int to) {
    for (const int f : PatchTree::triangles(to)) {
      const Tri& tri = tris[f];
      const Aabb fb = join(join(pbox[tri[0]], pbox[tri[1]]), pbox[tri[2]]);
      for (const int* p = t.vertices_begin(from); p != t.vertices_end(from); ++p) {
        if (*p == tri[0] || *p == tri[1] || *p == tri[2] || !meet(pbox[*p], fb)) continue;
        out.push_back({QueryKind::VertexFace, {*p, tri[0], tri[1], tri[2]}});
      }
    }
  };
  vf(a, b);
  if (a != b) vf(b, a);
  for (const int* e = t.edges_begin(a); e != t.edges_end(a); ++e) {
    const auto& ea = edges[*e];
    const Aabb eab = join(pbox[ea[0]], pbox[ea[1]]);
    for (const int* g = a == b ? e + 1 : t.edges_begin(b); g != t.edges_end(b); ++g) {
      const auto& eb = edges[*g];
      if (ea[0] == eb[0] || ea[0] == eb[1] || ea[1] == eb[0] || ea[1] == eb[1]) continue;
      if (!meet(eab, join(pbox[eb[0]], pbox[eb[1]]))) continue;
      out.push_back({QueryKind::EdgeEdge, {ea[0], ea[1], eb[0], eb[1]}});
    }
  }
}

// Grows every slab of b outward by h·|d|₁ for its direction d, plus pad: two points at most 2h
// apart project at most 2h·|d|₂ <= 2h·|d|₁ apart on d (Cauchy–Schwarz), so two boxes grown by h
// overlap when their contents come within 2h. pad covers the rounding of the subtraction.
template <int K>
void grow(Kdop<K>& b, double h, double pad) {
  for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
    const Direction& d = Kdop<K>::direction(s);
    const double g = (std::abs(d.x) + std::abs(d.y) + std::abs(d.z)) * h + pad;
    b.lo[s] -= g;
    b.hi[s] += g;
  }
}

// A candidate's four points in x.
std::array<Vec3, 4> points_of(const Candidate& c, const std::vector<Vec3>& x) {
  return {x[c.ids[0]], x[c.ids[1]], x[c.ids[2]], x[c.ids[3]]};
}

// Whether two of the pair's particles, one of each primitive, lie in one cell of the grid (rows
// and columns at most one apart): such a pair sits about 0.71 spacings apart at rest, and its
// springs, not the gap, keep it apart ("near by construction", docs/cloth.md).
bool shares_a_cell(const Candidate& c, int grid) {
  const int split = c.kind == QueryKind::VertexFace ? 1 : 2;
  for (int i = 0; i < split; ++i)
    for (int j = split; j < 4; ++j) {
      const int a = c.ids[i], b = c.ids[j];
      if (std::abs(a / grid - b / grid) <= 1 && std::abs(a % grid - b % grid) <= 1) return true;
    }
  return false;
}

// The first of a query's points that belong to its second primitive.
int first_of_second(QueryKind kind) {
  return kind == QueryKind::VertexFace ? 1 : 2;
}

// One pair's repulsion (Bridson, Fedkiw & Anderson 2002, §7.2, its inelastic part): a pair
// within `zone` at the start whose closest points approach along n loses that approach. dv is
// the change of velocity per unit weight: particle i of the pair changes by ±w_i·dv·n (+ on the
// first primitive), which changes the points' relative speed along n by Σ w_i²·dv = -v_n over
// the particles that may move (a pinned one does not).
struct Push {
  PairClosest at;  // the closest points at the start
  Vec3 n;          // their unit direction, from the second primitive to the first
  double dv = 0;   // 0: no push
};
Push push_of(const Candidate& c, const std::vector<Vec3>& x0, const std::vector<Vec3>& v,
             const Cloth& cloth, double zone) {
  Push p;
  if (shares_a_cell(c, cloth.grid())) return p;
  p.at = pair_closest(c.kind, points_of(c, x0));
  if (!(p.at.distance > 0 && p.at.distance < zone)) return p;
  p.n = (1 / p.at.distance) * p.at.dir;
  const int split = first_of_second(c.kind);
  Vec3 rel;
  double w2 = 0;
  for (int i = 0; i < 4; ++i) {
    const double w = i < split ? p.at.w[i] : -p.at.w[i];
    rel += w * v[c.ids[i]];
    if (!cloth.pinned(c.ids[i])) w2 += w * w;
  }
  const double vn = dot(rel, p.n);
  if (vn < 0 && w2 > 0) p.dv = -vn / w2;
  return p;
}

// Work for one thread: a cell against itself (b < 0) or two sibling patches.
struct Task {
  int a, b;
};

}  // namespace

template <int K>
struct SelfCollision::TreesK : SelfCollision::Trees {
  const Cloth& cloth;
  PatchTree tree;
  std::vector<Kdop<K>> particle_box, box;
  std::vector<Aabb> particle_aabb;  // particle_box's axis slabs
  std::vector<Task> tasks;
  std::vector<std::vector<Candidate>> parts;
  std::vector<char> dirty;  // per node: holds a changed particle

  double half_gap;  // each swept box grows by it (and a hair: grow()), so pairs within the gap meet

  TreesK(const Cloth& c, double gap) : cloth(c), tree(c), half_gap(0.5 * gap * (1 + 0x1p-40)) {}

  void candidates(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                  const std::vector<char>& changed, std::vector<Candidate>& out) override {
    tree.update_normals(x0, x1);
    mark_dirty(changed);
    tasks.clear();
    collect(0, x0, x1);
    if (tasks.empty()) return;  // the whole cloth is flat: nothing can touch
    refit(x0, x1);
    gather_chunks(int(tasks.size()), parts, out, [&](int i, std::vector<Candidate>& part) {
      const Task& t = tasks[i];
      if (t.b < 0)
        cell_pairs(tree, cloth, particle_aabb, tree.cell_of(tree.nodes()[t.a]),
                   tree.cell_of(tree.nodes()[t.a]), part);
      else
        patch_pairs(t.a, t.b, part);
    });
  }

  // Each node: whether a particle of its cells changed (every node when `changed` is empty).
  void mark_dirty(const std::vector<char>& changed) {
    dirty.assign(tree.nodes().size(), 1);
    if (changed.empty()) return;
    const int g = cloth.grid();
    tree.bottom_up([&](int i) {
      const auto& nd = tree.nodes()[i];
      const int a = nd.r0 * g + nd.c0;
      dirty[i] = nd.leaf() ? changed[a] || changed[a + 1] || changed[a + g] || changed[a + g + 1]
                           : dirty[nd.left] || dirty[nd.right];
    });
  }

  // Top down: a flat node needs nothing, nor one without a changed particle; otherwise its
  // cell, or its children and their pair.
  void collect(int node, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
    if (!dirty[node] || tree.flat(node, x0, x1)) return;
    const auto& n = tree.nodes()[node];
    if (n.leaf()) {
      tasks.push_back({node, -1});
      return;
    }
    collect(n.left, x0, x1);
    collect(n.right, x0, x1);
    tasks.push_back({n.left, n.right});
  }

  // Swept boxes: each particle's, then each cell's (its four corners), then up the tree.
  void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
    const int n = int(x0.size()), g = cloth.grid();
    particle_box.resize(n);
    particle_aabb.resize(n);
    box.resize(tree.nodes().size());
    for_chunks(n, 4096, [&](int begin, int end) {
      for (int i = begin; i < end; ++i) {
        const double ma = max_abs(x0[i]), mb = max_abs(x1[i]);
        const double m = ma > mb ? ma : mb;
        set_segment(particle_box[i], x0[i], x1[i], widening_of(m));
        if (half_gap > 0) grow(particle_box[i], half_gap, widening_of(4 * (m + half_gap)));
        const Kdop<K>& b = particle_box[i];  // slabs 0-2 are x, y and z for every k
        particle_aabb[i] = {{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
      }
    });
    const auto& nodes = tree.nodes();
    tree.bottom_up([&](int i) {
      const auto& nd = nodes[i];
      if (nd.leaf()) {
        const int a = nd.r0 * g + nd.c0;
        box[i] = merge(merge(particle_box[a], particle_box[a + 1]),
                       merge(particle_box[a + g], particle_box[a + g + 1]));
      } else {
        box[i] = merge(box[nd.left], box[nd.right]);
      }
    });
  }

  // Two disjoint patches, tree against tree: the larger one descended while their boxes meet.
  void patch_pairs(int a, int b, std::vector<Candidate>& out) const {
    const auto& nodes = tree.nodes();
    const auto cells = [&](int i) {
      return (nodes[i].r1 - nodes[i].r0) * (nodes[i].c1 - nodes[i].c0);
    };
    thread_local std::vector<std::pair<int, int>> stack;  // one per thread: no allocation per task
    stack.assign(1, {a, b});
    while (!stack.empty()) {
      const auto [i, j] = stack.back();
      stack.pop_back();
      if ((!dirty[i] && !dirty[j]) || !overlap(box[i], box[j])) continue;
      const auto &ni = nodes[i], &nj = nodes[j];
      if (ni.leaf() && nj.leaf()) {
        cell_pairs(tree, cloth, particle_aabb, tree.cell_of(ni), tree.cell_of(nj), out);
      } else if (!ni.leaf() && (nj.leaf() || cells(i) >= cells(j))) {
        stack.push_back({ni.right, j});
        stack.push_back({ni.left, j});
      } else {
        stack.push_back({i, nj.right});
        stack.push_back({i, nj.left});
      }
    }
  }
};

SelfCollision::SelfCollision(const Cloth& cloth, int k, CcdTest exact, ExactToi exact_toi,
                             int rounds, double gap, double dt)
    : cloth_(cloth), exact_(exact), exact_toi_(exact_toi), rounds_(rounds), gap_(gap), dt_(dt) {
  if (!exact_ || !exact_toi_)
    throw std::invalid_argument("self-collision needs an exact CCD fallback");
  if (!(gap >= 0 && gap <= 0x1p100))
    throw std::invalid_argument("the self-collision gap must be finite and >= 0");
  trees_ = with_k(k, [&](auto kc) -> std::unique_ptr<Trees> {
    return std::make_unique<TreesK<decltype(kc)::value>>(cloth, gap);
  });
}

// A margin of 2^-20 of the gap keeps the float distance's rounding (about 2^-52 of the
// coordinates) on the right side: a pair at rest is never within the gap it is tested at.
double SelfCollision::gap_of(double start_distance) const {
  constexpr double kMargin = 1 + 0x1p-20;
  if (start_distance > gap_ * kMargin) return gap_;
  return start_distance > 0.5 * gap_ * kMargin ? 0.5 * gap_ : 0;
}

double SelfCollision::min_distance(const std::vector<Vec3>& x) const {
  double d = std::numeric_limits<double>::infinity();
  const auto measure = [&](const std::vector<Candidate>& list) {
    for (const Candidate& c : list)
      if (!shares_a_cell(c, cloth_.grid())) d = std::min(d, pair_distance(c.kind, points_of(c, x)));
  };
  measure(candidates_);
  if (!changed_.empty()) measure(first_);  // a later search held only the stopped particles'
  return d;
}

SelfCollision::~SelfCollision() = default;

void SelfCollision::contacts(const std::vector<Vec3>& x0, const std::vector<Vec3>& x, Result& r,
                             bool search) {
  if (search) candidates_.clear(), trees_->candidates(x0, x, changed_, candidates_);
  hit_.assign(candidates_.size(), 0);
  // After a round of stops only pairs with a stopped particle can change their verdict: the
  // others move as they did in the round's test (which found them apart) or, new candidates,
  // lie in a patch that was flat for that same motion.
  const auto moved = [&](const Candidate& c) {
    return changed_.empty() || changed_[c.ids[0]] || changed_[c.ids[1]] || changed_[c.ids[2]] ||
           changed_[c.ids[3]];
  };
  long tested = 0;
  for (const Candidate& c : candidates_) tested += moved(c);
  for_chunks(int(candidates_.size()), 256, [&](int begin, int end) {
    for (int c = begin; c < end; ++c) {
      Candidate& cand = candidates_[c];
      if (!moved(cand)) continue;
      Query q;
      q.kind = cand.kind;
      for (int i = 0; i < 4; ++i) q.x[i] = x0[cand.ids[i]], q.x[i + 4] = x[cand.ids[i]];
      if (gap_ > 0 && !shares_a_cell(cand, cloth_.grid()))
        cand.gap = gap_of(pair_distance(cand.kind, points_of(cand, x0)));
      q.min_distance = cand.gap;
      hit_[c] = robust_ccd(q, exact_);
    }
  });
  touching_.clear();
  for (std::size_t c = 0; c < candidates_.size(); ++c)
    if (hit_[c]) touching_.push_back(candidates_[c]);
  r.queries += tested;
  r.hits += long(touching_.size());
}

void SelfCollision::stop_at_impact(const std::vector<Vec3>& x0, std::vector<Vec3>& x,
                                   std::vector<Vec3>& v) {
  toi_.assign(touching_.size(), 1);
  for_chunks(int(touching_.size()), 64, [&](int begin, int end) {
    for (int c = begin; c < end; ++c) {
      Query q;
      q.kind = touching_[c].kind;
      for (int i = 0; i < 4; ++i) {
        q.x[i] = x0[touching_[c].ids[i]];
        q.x[i + 4] = x[touching_[c].ids[i]];
      }
      q.min_distance = touching_[c].gap;  // the same question as the test's
      toi_[c] = robust_ccd_toi(q, kDefaultToiWidth, exact_toi_).t_lo;
    }
  });
  stop_.assign(x.size(), 2);  // 2: not in a touching pair
  for (std::size_t c = 0; c < touching_.size(); ++c)
    for (const int i : touching_[c].ids) stop_[i] = std::min(stop_[i], toi_[c]);
  changed_.assign(x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (stop_[i] > 1) continue;
    changed_[i] = 1;
    // t_lo = 0 puts it back at the start exactly (0 only when the pair touches there).
    x[i] = stop_[i] == 0 ? x0[i] : x0[i] + stop_[i] * (x[i] - x0[i]);
    v[i] = Vec3{};
  }
}

long SelfCollision::repel(const std::vector<Vec3>& x0, std::vector<Vec3>& v) {
  std::vector<Push> push(candidates_.size());
  const double zone = kRepelZone * gap_;
  for_chunks(int(candidates_.size()), 256, [&](int begin, int end) {
    for (int c = begin; c < end; ++c) push[c] = push_of(candidates_[c], x0, v, cloth_, zone);
  });
  dv_.assign(v.size(), Vec3{});
  count_.assign(v.size(), 0);
  long pushed = 0;
  for (std::size_t c = 0; c < candidates_.size(); ++c) {  // in order: the same sums on any thread
    if (push[c].dv == 0) continue;
    ++pushed;
    const int split = first_of_second(candidates_[c].kind);
    for (int i = 0; i < 4; ++i) {
      const int id = candidates_[c].ids[i];
      if (cloth_.pinned(id)) continue;
      const double w = i < split ? push[c].at.w[i] : -push[c].at.w[i];
      dv_[id] += (w * push[c].dv) * push[c].n;
      ++count_[id];
    }
  }
  for (std::size_t i = 0; i < v.size(); ++i)
    if (count_[i]) v[i] += (1.0 / count_[i]) * dv_[i];  // the mean of its pairs' pushes
  return pushed;
}

namespace {

// Union–find over the particles, for the impact zones.
struct Zones {
  std::vector<int> parent;
  explicit Zones(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

SelfCollision::Result SelfCollision::resolve(const std::vector<Vec3>& x0, std::vector<Vec3>& x,
                                             std::vector<Vec3>& v) {
  const std::vector<Vec3> x_in = x;
  Result r = stages(x0, x, v);
  if (!r.stopped_all) r.min_distance = min_distance(x);  // the last test's pairs, where they end
  if (r.hits == 0) return r;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(x[i] == x_in[i])) r.motion += norm(x_in[i] - x0[i]), r.kept += norm(x[i] - x0[i]);
  return r;
}

SelfCollision::Result SelfCollision::stages(const std::vector<Vec3>& x0, std::vector<Vec3>& x,
                                            std::vector<Vec3>& v) {
  Result r;
  changed_.clear();  // the first search and test take every candidate
  const bool repelling = gap_ > 0 && dt_ > 0;
  if (repelling) {
    candidates_.clear();
    trees_->candidates(x0, x, changed_, candidates_);
    r.repelled = repel(x0, v);  // velocities only: x and so the candidates stay
  }
  std::vector<Vec3> v_in;  // the velocities before any response, for the zones' means
  const int rounds = rounds_ > 0 ? rounds_ + kStartRounds : 0;
  for (int round = 0; round < rounds; ++round) {  // stage 1
    contacts(x0, x, r, round > 0 || !repelling);
    if (touching_.empty()) return r;
    if (round == 0) first_ = candidates_;
    if (v_in.empty()) v_in = v;
    ++r.rounds;
    if (round < rounds_)
      stop_at_impact(x0, x, v);
    else
      stop_at_start(x0, x, v);
  }
  contacts(x0, x, r, rounds > 0 || !repelling);
  if (touching_.empty()) return r;
  if (v_in.empty()) v_in = v;
  zone_stage(x0, x, v, v_in, r);
  return r;
}

void SelfCollision::stop_at_start(const std::vector<Vec3>& x0, std::vector<Vec3>& x,
                                  std::vector<Vec3>& v) {
  changed_.assign(x.size(), 0);
  for (const Candidate& c : touching_)
    for (const int i : c.ids) x[i] = x0[i], v[i] = Vec3{}, changed_[i] = 1;
}

void SelfCollision::zone_stage(const std::vector<Vec3>& x0, std::vector<Vec3>& x,
                               std::vector<Vec3>& v, const std::vector<Vec3>& v_in, Result& r) {
  r.zones = true;    // stage 2
  changed_.clear();  // every candidate, in every iteration
  const int n = int(x.size());
  Zones zones(n);
  std::vector<char> in_zone(n, 0);
  for (int round = 0; round < kZoneRounds && !touching_.empty(); ++round) {
    for (const Candidate& c : touching_)
      for (const int i : c.ids) zones.join(c.ids[0], i), in_zone[i] = 1;
    std::vector<Vec3> sum(n);
    std::vector<int> count(n, 0);
    for (int i = 0; i < n; ++i)
      if (in_zone[i]) sum[zones.find(i)] += v_in[i], ++count[zones.find(i)];
    for (int i = 0; i < n; ++i) {
      if (!in_zone[i]) continue;
      const int z = zones.find(i);
      x[i] = x0[i];
      v[i] = (1.0 / count[z]) * sum[z];  // the zone's mean velocity: momentum kept
    }
    contacts(x0, x, r);
  }
  r.zone_particles = std::count(in_zone.begin(), in_zone.end(), 1);
  if (touching_.empty()) return;
  x = x0;  // stage 3: still in contact after every zone iteration
  for (Vec3& u : v) u = Vec3{};
  r.stopped_all = true;
}

}  // namespace fdh::cloth
