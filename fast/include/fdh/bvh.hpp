// The FDH tree of Han & Jia 2013 §2-3: built top down, refit bottom up, traversed tree
// against tree.
// - Split direction: the direction of D along which the node is longest, in world units
//   (slab width / |d|, so diagonals are not favoured by their length), judged on the centres of
//   at most 16 of its primitives, evenly spaced (a constant cost per node).
// - Split value: the median of the primitives' centroid projections on it (nth_element, so the
//   halves are balanced even when projections tie).
// - Leaves: `leaf_size` primitives, 1 by default as in the paper.
// - Swept leaves: given positions at the start (x0) and end (x1) of a step, a leaf covers its
//   primitives at both, so that nothing tunnels between steps. Conservative k-DOPs keep the
//   whole tree conservative: merging takes exact minima and maxima.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "fdh/kdop.hpp"

namespace fdh {

// A primitive: three vertex indices. A point is {i, i, i}, an edge {i, j, j}.
using Tri = std::array<int, 3>;

// Points 0 .. n-1 as primitives, for a tree over particles.
inline std::vector<Tri> point_prims(int n) {
  std::vector<Tri> t(n);
  for (int i = 0; i < n; ++i) t[i] = {i, i, i};
  return t;
}

template <int K>
class Bvh {
 public:
  struct Node {
    Node() {}  // the box is written before it is read: no zeroing of 8·k bytes per node
    Kdop<K> box;
    int left = -1, right = -1;  // children, for an internal node; a leaf of one point: right
                                // is that point's vertex (what a refit reads first)
    int first = 0, count = 0;   // a leaf's range in prims()
    bool leaf() const { return count > 0; }
  };

  // x1 empty: a static tree over x0. Otherwise swept over x0 and x1 (same size).
  Bvh(std::vector<Tri> tris, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1 = {},
      int leaf_size = 1)
      : Bvh(std::move(tris), x0, x1, leaf_size, [](int n, const auto& f) {
          for (int i = 0; i < n; ++i) f(i);
        }) {}

  // The same tree, its subtrees below depth 6 built by spread(n, f), which calls f(i) for every
  // i in [0, n), at the same time or not (fast/ starts no thread: the caller's loop, e.g.
  // fdh/parallel/chunks.hpp's for_each_index). Nodes are numbered by the subtrees' sizes alone
  // (a subtree of m primitives has node_count(m) nodes), so the tree is the one built in order.
  template <class Spread>
  Bvh(std::vector<Tri> tris, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
      int leaf_size, const Spread& spread)
      : tris_(std::move(tris)), leaf_size_(std::max(1, leaf_size)) {
    const int n = int(tris_.size());
    // Each primitive's centre (the sum of its corners: the centroid up to a factor) once; the
    // items the splits reorder are only a key and an index (16 bytes: nth_element moves less).
    std::vector<Item> items(n);
    centres_.resize(n);
    for (int i = 0; i < n; ++i) {
      Vec3 c{};
      for (const int v : tris_[i]) c += x1.empty() ? x0[v] : x0[v] + x1[v];
      centres_[i] = c;
      items[i] = {0.0, i};
    }
    prims_.resize(n);
    if (n > 0) {
      nodes_.resize(std::size_t(node_count(n)));
      std::vector<Range> below;
      std::vector<int> top;
      build_top(0, 0, n, 0, items, below, top);
      spread(int(below.size()),
             [&](int r) { build(below[r].id, below[r].first, below[r].last, items, x0, x1); });
      for (auto i = top.rbegin(); i != top.rend(); ++i) {  // children before parents
        Node& node = nodes_[*i];
        merge_into(node.box, nodes_[node.left].box, nodes_[node.right].box);
      }
    }
    centres_ = {};
  }

  // New positions, same topology: leaves recomputed, internal nodes merged bottom up (children
  // always follow their parent in nodes()).
  void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1 = {}) {
    const double w = widening(x0, x1);
    for (int i = int(nodes_.size()) - 1; i >= 0; --i) refit_node(i, x0, x1, w);
  }

  // One widening for every leaf of a refit: kdop.hpp's bound for the largest coordinate of all
  // the points covers each leaf's own (a larger mag only widens more). Four running maxima, so
  // that the pass is not one long chain of dependent comparisons.
  static double widening(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
    double m[4] = {0, 0, 0, 0};
    for (const std::vector<Vec3>* x : {&x0, &x1}) {
      const double* p = x->empty() ? nullptr : &(*x)[0].x;
      const std::size_t n = 3 * x->size();
      std::size_t i = 0;
      for (; i + 4 <= n; i += 4)
        for (int k = 0; k < 4; ++k) {
          const double a = std::fabs(p[i + k]);
          m[k] = a > m[k] ? a : m[k];
        }
      for (; i < n; ++i) m[0] = std::max(m[0], std::fabs(p[i]));
    }
    return widening_of(std::max(std::max(m[0], m[1]), std::max(m[2], m[3])));
  }

  // One node of a refit: a leaf from the positions (widened by w, from widening()), an
  // internal node from its children (which must be refit already). Nodes are in preorder, so
  // a subtree is a range of indices: refitting such a range from its end is a refit of that
  // subtree, and disjoint subtrees can be refit at the same time.
  void refit_node(int i, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, double w) {
    Node& n = nodes_[i];
    if (n.leaf()) {
      if (n.right >= 0) {  // one point: the cloth's leaves
        set_segment(n.box, x0[n.right], x1.empty() ? x0[n.right] : x1[n.right], w);
      } else {
        range_box(n.box, n.first, n.first + n.count, x0, x1);
      }
      return;
    }
    merge_into(n.box, nodes_[n.left].box, nodes_[n.right].box);
  }

  bool empty() const { return nodes_.empty(); }
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int>& prims() const { return prims_; }  // primitive indices, leaf by leaf
  const std::vector<Tri>& tris() const { return tris_; }

 private:
  // The box of primitives prims_[first, last): their distinct vertices at x0 (and x1).
  void range_box(Kdop<K>& b, int first, int last, const std::vector<Vec3>& x0,
                 const std::vector<Vec3>& x1) const {
    KdopBuilder<K> builder;
    for (int i = first; i < last; ++i) {
      const Tri& t = tris_[prims_[i]];
      for (int c = 0; c < 3; ++c) {
        if ((c > 0 && t[c] == t[c - 1]) || (c == 2 && t[2] == t[0])) continue;  // points, edges
        builder.add(x0[t[c]]);
        if (!x1.empty()) builder.add(x1[t[c]]);
      }
    }
    b = builder.finish();
  }

  struct Item {
    double key;
    int prim;
  };

  // The nodes of a subtree over n primitives: one, or one and its two halves'.
  int node_count(int n) const {
    if (n <= leaf_size_) return 1;
    if (leaf_size_ == 1) return 2 * n - 1;
    return 1 + node_count(n / 2) + node_count(n - n / 2);
  }

  // A subtree left for spread(): its root's index and its primitives' range in items.
  struct Range {
    int id, first, last;
  };

  // The nodes above depth 6 over items[first, last), split and numbered (their boxes are merged
  // once the subtrees below are built): `top` in preorder, the subtrees at depth 6 in `below`.
  void build_top(int id, int first, int last, int depth, std::vector<Item>& items,
                 std::vector<Range>& below, std::vector<int>& top) {
    if (depth == 6 || last - first <= leaf_size_) {
      below.push_back({id, first, last});
      return;
    }
    const int mid = first + (last - first) / 2;
    if (last - first > 2) median_split(first, mid, last, items);  // two: already one a side
    top.push_back(id);
    nodes_[id].left = id + 1;
    nodes_[id].right = id + 1 + node_count(mid - first);
    build_top(nodes_[id].left, first, mid, depth + 1, items, below, top);
    build_top(nodes_[id].right, mid, last, depth + 1, items, below, top);
  }

  // Node `id` over items[first, last) and, below it, its subtree (nodes id to id +
  // node_count(last - first) - 1, in preorder). A leaf's box comes from its primitives' corners,
  // an internal node's from its children's boxes merged: one merge per node.
  void build(int id, int first, int last, std::vector<Item>& items, const std::vector<Vec3>& x0,
             const std::vector<Vec3>& x1) {
    Node& node = nodes_[id];
    if (last - first <= leaf_size_) {
      for (int i = first; i < last; ++i) prims_[i] = items[i].prim;
      const Tri& t = tris_[items[first].prim];
      if (last - first == 1 && t[0] == t[1] && t[1] == t[2]) {  // one point: its own widening
        const Vec3 &p0 = x0[t[0]], &p1 = x1.empty() ? p0 : x1[t[0]];
        set_segment(node.box, p0, p1, widening_of(std::max(max_abs(p0), max_abs(p1))));
        node.right = t[0];
      } else {
        range_box(node.box, first, last, x0, x1);
      }
      node.first = first;
      node.count = last - first;
      return;
    }
    const int mid = first + (last - first) / 2;
    if (last - first > 2) median_split(first, mid, last, items);  // two: already one a side
    node.left = id + 1;
    node.right = id + 1 + node_count(mid - first);
    build(node.left, first, mid, items, x0, x1);
    build(node.right, mid, last, items, x0, x1);
    merge_into(node.box, nodes_[node.left].box, nodes_[node.right].box);
  }

  // Orders items[first, last) so that [first, mid) holds the ones whose centres come first
  // along the direction in which a sample of them spreads widest (ties in any order).
  void median_split(int first, int mid, int last, std::vector<Item>& items) const {
    const Direction& d = Kdop<K>::direction(longest_slab(sample_box(first, last, items)));
    const double dx = d.x, dy = d.y, dz = d.z;  // as project() computes it, converted once
    for (int i = first; i < last; ++i) {
      const Vec3& c = centres_[items[i].prim];
      items[i].key = dx * c.x + dy * c.y + dz * c.z;
    }
    const auto by_key = [](const Item& a, const Item& b) { return a.key < b.key; };
    std::nth_element(items.begin() + first, items.begin() + mid, items.begin() + last, by_key);
  }

  // The k-DOP of the centres of at most 16 of the range's primitives, evenly spaced: enough to
  // choose the split direction (the split itself is the exact median), at a constant cost per
  // node. Only its shape is used, so it needs no widening.
  Kdop<K> sample_box(int first, int last, const std::vector<Item>& items) const {
    const int n = last - first, m = std::min(n, 16);
    const double step = double(n - 1) / (m - 1);  // no integer division per sample
    Kdop<K> b = Kdop<K>::empty();
    for (int i = 0; i < m; ++i) {
      const std::array<double, 13> v = projections(centres_[items[first + int(i * step)].prim]);
      for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
        const double x = v[Kdop<K>::kDirIndex[s]];
        b.lo[s] = x < b.lo[s] ? x : b.lo[s];
        b.hi[s] = x > b.hi[s] ? x : b.hi[s];
      }
    }
    return b;
  }

  // The slab along which b is longest, in world units (width / |d|).
  static int longest_slab(const Kdop<K>& b) {
    // 1/|d| for the axes, the corner diagonals and the edge diagonals of kDirections.
    static const std::array<double, 3> inv_len = {1.0, 1 / std::sqrt(3.0), 1 / std::sqrt(2.0)};
    int axis = 0;
    double longest = -1;
    for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
      const int i = Kdop<K>::kDirIndex[s];
      const double len = (b.hi[s] - b.lo[s]) * inv_len[i < 3 ? 0 : i < 7 ? 1 : 2];
      if (len > longest) axis = s, longest = len;
    }
    return axis;
  }

  std::vector<Tri> tris_;
  int leaf_size_;
  std::vector<Vec3> centres_;  // each primitive's, during the build
  std::vector<int> prims_;
  std::vector<Node> nodes_;
};

// TraverseTree(A, B) of §3: every pair (a, b) of primitives of A and B whose leaf k-DOPs
// overlap, in (A, B) order, appended to `out`. The printed pseudo-code recurses as
// TraverseTree(Cb, A), swapping its arguments so that both trees are descended in turn; this
// descends the node with the larger box (by its x, y and z widths), so a small cloth patch
// is not tested against every level of a large obstacle one leaf at a time, and keeps each
// pair's roles. With first_slab >= 0 every box test checks that slab first (§3.1's early-out).
template <int K>
double size(const Kdop<K>& b) {  // slabs 0-2 are the axes for every k
  return (b.hi[0] - b.lo[0]) + (b.hi[1] - b.lo[1]) + (b.hi[2] - b.lo[2]);
}

// The children to descend into from the overlapping node pair (i, j): the larger box's (or the
// one that is not a leaf), as (first, second); none for two leaves.
template <int K>
[[gnu::always_inline]] inline bool split_pair(const Bvh<K>& a, const Bvh<K>& b, int i, int j,
                                              std::pair<int, int>& first,
                                              std::pair<int, int>& second) {
  const auto& na = a.nodes()[i];
  const auto& nb = b.nodes()[j];
  if (!na.leaf() && (nb.leaf() || size(na.box) >= size(nb.box))) {
    first = {na.left, j}, second = {na.right, j};
  } else if (!nb.leaf()) {
    first = {i, nb.left}, second = {i, nb.right};
  } else {
    return false;
  }
  return true;
}

// Every pair of primitives under the node pairs on `stack`, one from each side, whose leaf
// boxes overlap: the loop of traverse() and traverse_self(). The pairs given are tested first;
// below them, both children of a split pair are tested before either is pushed, so a pair that
// does not overlap never goes through the stack, and the first is descended at once (same
// pairs, same order, as pushing both and testing on pop).
template <int K, class Overlaps>
void descend_pairs(const Bvh<K>& a, const Bvh<K>& b, std::vector<std::pair<int, int>>& stack,
                   std::vector<std::pair<int, int>>& out, const Overlaps& overlaps) {
  const auto* A = a.nodes().data();
  const auto* B = b.nodes().data();
  const auto meet = [&](const std::pair<int, int>& p) {
    return overlaps(A[p.first].box, B[p.second].box);
  };
  stack.erase(std::remove_if(stack.begin(), stack.end(), [&](const auto& p) { return !meet(p); }),
              stack.end());
  while (!stack.empty()) {
    auto [i, j] = stack.back();
    stack.pop_back();
    // Down the first child pair without the stack while it meets; the second waits there.
    bool meets = true;
    for (std::pair<int, int> first, second; meets && split_pair(a, b, i, j, first, second);) {
      if (meet(second)) stack.push_back(second);
      meets = meet(first);
      std::tie(i, j) = first;
    }
    if (!meets) continue;
    for (int p = A[i].first; p < A[i].first + A[i].count; ++p)
      for (int q = B[j].first; q < B[j].first + B[j].count; ++q)
        out.push_back({a.prims()[p], b.prims()[q]});
  }
}

// Node pairs whose descents together make traverse()'s: the root pair split by the same rule,
// level by level, until there are at least `want` (or nothing left to split). Each can then be
// descended on its own (descend_pairs), and the outputs joined in this order.
template <int K, class Overlaps>
std::vector<std::pair<int, int>> frontier(const Bvh<K>& a, const Bvh<K>& b, std::size_t want,
                                          const Overlaps& overlaps) {
  std::vector<std::pair<int, int>> level;
  if (a.empty() || b.empty()) return level;
  level.push_back({0, 0});
  for (bool split = true; split && level.size() < want;) {
    split = false;
    std::vector<std::pair<int, int>> next;
    for (const auto& [i, j] : level) {
      if (!overlaps(a.nodes()[i].box, b.nodes()[j].box)) continue;
      std::pair<int, int> first, second;
      if (split_pair(a, b, i, j, first, second)) {
        next.push_back(first);
        next.push_back(second);
        split = true;
      } else {
        next.push_back({i, j});
      }
    }
    level.swap(next);
  }
  return level;
}

template <int K>
void traverse(const Bvh<K>& a, const Bvh<K>& b, std::vector<std::pair<int, int>>& out,
              int first_slab = -1) {
  if (a.empty() || b.empty()) return;
  std::vector<std::pair<int, int>> stack;
  stack.reserve(128);  // a descent holds at most about one pair per level of each tree
  stack.push_back({0, 0});
  if (first_slab >= 0)
    descend_pairs(a, b, stack, out, [first_slab](const Kdop<K>& x, const Kdop<K>& y) {
      return overlap(x, y, first_slab);
    });
  else
    descend_pairs(a, b, stack, out,
                  [](const Kdop<K>& x, const Kdop<K>& y) { return overlap(x, y); });
}

// A tree against itself (self-collision): every unordered pair of distinct primitives whose
// leaf boxes overlap, once, as (a, b) in some order. Each node's two children are traversed
// against each other, and each child against itself: no node pair is visited twice, and no
// primitive is paired with itself (traverse(t, t) would do both).
template <int K>
void traverse_self(const Bvh<K>& t, std::vector<std::pair<int, int>>& out) {
  if (t.empty()) return;
  std::vector<std::pair<int, int>> stack;
  const auto overlaps = [](const Kdop<K>& x, const Kdop<K>& y) { return overlap(x, y); };
  std::vector<int> pending = {0};
  while (!pending.empty()) {
    const auto& n = t.nodes()[pending.back()];
    pending.pop_back();
    if (n.leaf()) {
      for (int p = n.first; p < n.first + n.count; ++p)
        for (int q = p + 1; q < n.first + n.count; ++q) out.push_back({t.prims()[p], t.prims()[q]});
      continue;
    }
    pending.push_back(n.left);
    pending.push_back(n.right);
    stack.push_back({n.left, n.right});
    descend_pairs(t, t, stack, out, overlaps);
  }
}

}  // namespace fdh
