// The FDH tree of Han & Jia 2013 §2-3: built top down, refit bottom up, traversed tree
// against tree.
// - Split direction: the direction of D along which the node's FDH is longest, in world units
//   (slab width / |d|, so diagonals are not favoured by their length).
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
#include <utility>
#include <vector>

#include "fdh/kdop.hpp"

namespace fdh {

// A primitive: three vertex indices. A point is {i, i, i}, an edge {i, j, j}.
using Tri = std::array<int, 3>;

template <int K>
class Bvh {
 public:
  struct Node {
    Kdop<K> box;
    int left = -1, right = -1;  // children, for an internal node
    int first = 0, count = 0;   // a leaf's range in prims()
    bool leaf() const { return count > 0; }
  };

  // x1 empty: a static tree over x0. Otherwise swept over x0 and x1 (same size).
  Bvh(std::vector<Tri> tris, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1 = {},
      int leaf_size = 1)
      : tris_(std::move(tris)), leaf_size_(std::max(1, leaf_size)) {
    prims_.resize(tris_.size());
    for (std::size_t i = 0; i < prims_.size(); ++i) prims_[i] = int(i);
    // Each primitive's box once; a node's box is the exact merge of its primitives' boxes.
    std::vector<Kdop<K>> boxes(tris_.size());
    for (std::size_t i = 0; i < tris_.size(); ++i) boxes[i] = prim_box(int(i), x0, x1);
    if (!tris_.empty()) build(0, int(tris_.size()), boxes, x0, x1);
  }

  // New positions, same topology: leaves recomputed, internal nodes merged bottom up (children
  // always follow their parent in nodes()).
  void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1 = {}) {
    for (int i = int(nodes_.size()) - 1; i >= 0; --i) {
      Node& n = nodes_[i];
      n.box = n.leaf() ? range_box(n.first, n.first + n.count, x0, x1)
                       : merge(nodes_[n.left].box, nodes_[n.right].box);
    }
  }

  bool empty() const { return nodes_.empty(); }
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int>& prims() const { return prims_; }  // primitive indices, leaf by leaf
  const std::vector<Tri>& tris() const { return tris_; }

 private:
  Kdop<K> prim_box(int prim, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) const {
    KdopBuilder<K> b;
    for (const int v : tris_[prim]) {
      b.add(x0[v]);
      if (!x1.empty()) b.add(x1[v]);
    }
    return b.finish();
  }

  Kdop<K> range_box(int first, int last, const std::vector<Vec3>& x0,
                    const std::vector<Vec3>& x1) const {
    Kdop<K> b = prim_box(prims_[first], x0, x1);
    for (int i = first + 1; i < last; ++i) b = merge(b, prim_box(prims_[i], x0, x1));
    return b;
  }

  int build(int first, int last, const std::vector<Kdop<K>>& boxes, const std::vector<Vec3>& x0,
            const std::vector<Vec3>& x1) {
    const int id = int(nodes_.size());
    nodes_.emplace_back();
    Node node;
    node.box = boxes[prims_[first]];
    for (int i = first + 1; i < last; ++i) node.box = merge(node.box, boxes[prims_[i]]);
    if (last - first <= leaf_size_) {
      node.first = first;
      node.count = last - first;
      nodes_[id] = node;
      return id;
    }
    int axis = 0;
    double longest = -1;
    for (int s = 0; s < Kdop<K>::kSlabs; ++s) {
      const Direction& d = Kdop<K>::direction(s);
      const double len =
          (node.box.hi[s] - node.box.lo[s]) / std::sqrt(double(d.x * d.x + d.y * d.y + d.z * d.z));
      if (len > longest) axis = s, longest = len;
    }
    const Direction& d = Kdop<K>::direction(axis);
    const auto centre = [&](int prim) {  // sum of the corners: the centroid up to a factor
      double c = 0;
      for (const int v : tris_[prim])
        c += project(d, x0[v]) + (x1.empty() ? 0.0 : project(d, x1[v]));
      return c;
    };
    const int mid = first + (last - first) / 2;
    std::nth_element(prims_.begin() + first, prims_.begin() + mid, prims_.begin() + last,
                     [&](int a, int b) { return centre(a) < centre(b); });
    node.left = build(first, mid, boxes, x0, x1);
    node.right = build(mid, last, boxes, x0, x1);
    nodes_[id] = node;
    return id;
  }

  std::vector<Tri> tris_;
  int leaf_size_;
  std::vector<int> prims_;
  std::vector<Node> nodes_;
};

// TraverseTree(A, B) of §3: every pair (a, b) of primitives of A and B whose leaf k-DOPs
// overlap, in (A, B) order, appended to `out`. The printed pseudo-code recurses as
// TraverseTree(Cb, A), swapping its arguments; what it means, and what this does, is: descend
// A while A's node is internal, then descend B, and keep each pair's roles. With
// first_slab >= 0 every box test checks that slab first (§3.1's early-out).
template <int K>
void traverse(const Bvh<K>& a, const Bvh<K>& b, std::vector<std::pair<int, int>>& out,
              int first_slab = -1) {
  if (a.empty() || b.empty()) return;
  const auto overlaps = [first_slab](const Kdop<K>& x, const Kdop<K>& y) {
    return first_slab >= 0 ? overlap(x, y, first_slab) : overlap(x, y);
  };
  std::vector<std::pair<int, int>> stack = {{0, 0}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const auto& na = a.nodes()[i];
    const auto& nb = b.nodes()[j];
    if (!overlaps(na.box, nb.box)) continue;
    if (!na.leaf()) {
      stack.push_back({na.right, j});
      stack.push_back({na.left, j});
    } else if (!nb.leaf()) {
      stack.push_back({i, nb.right});
      stack.push_back({i, nb.left});
    } else {
      for (int p = na.first; p < na.first + na.count; ++p)
        for (int q = nb.first; q < nb.first + nb.count; ++q)
          out.push_back({a.prims()[p], b.prims()[q]});
    }
  }
}

}  // namespace fdh
