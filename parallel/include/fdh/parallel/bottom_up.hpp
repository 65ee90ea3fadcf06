// A pass over a binary tree stored in preorder, children before parents, on every core, with a
// result that does not depend on the thread count: the one bottom-up pass of the cloth's trees
// and the audit's (fdh/parallel/chunks.hpp underneath).
#pragma once

#include <cstddef>
#include <vector>

#include "fdh/parallel/chunks.hpp"

namespace fdh::parallel {

// The index one past node i's subtree in a binary tree stored in preorder (each subtree a
// contiguous range of nodes): the last leaf reached going right, plus one. Node: leaf(), right.
template <class Node>
int subtree_end(const std::vector<Node>& nodes, int i) {
  while (!nodes[i].leaf()) i = nodes[i].right;
  return i + 1;
}

// Below this many tree nodes (a cloth of about 90x90 particles) a pass over a tree, and the
// cloth's traversal, stay on the calling thread: waking the others would cost more.
inline constexpr std::size_t kParallelNodes = 1 << 14;

// A pass over a binary tree in preorder, children before parents, on every core: the subtrees
// at depth 6 (64, or the leaves above that depth) side by side, then the 63 nodes above them on
// the calling thread. A tree smaller than `parallel_nodes` stays on the calling thread (waking
// the others would cost more than the pass). Every node is visited once either way, after its
// children, so a pass that only writes the node it visits gives the same result on any number
// of threads.
class BottomUp {
 public:
  BottomUp() = default;  // no nodes
  template <class Node>
  explicit BottomUp(const std::vector<Node>& nodes, std::size_t parallel_nodes = kParallelNodes)
      : size_(int(nodes.size())) {
    if (nodes.size() >= parallel_nodes) split(nodes, 0, 0);
  }
  // f(i) for every node i.
  template <class F>
  void run(const F& f) const {
    if (roots_.empty()) {
      for (int i = size_ - 1; i >= 0; --i) f(i);
      return;
    }
    for_chunks(int(roots_.size()), 1, [&](int begin, int end) {
      for (int r = begin; r < end; ++r)
        for (int i = ends_[r] - 1; i >= roots_[r]; --i) f(i);
    });
    for (auto i = top_.rbegin(); i != top_.rend(); ++i) f(*i);
  }

 private:
  template <class Node>
  void split(const std::vector<Node>& nodes, int node, int depth) {
    if (depth == 6 || nodes[node].leaf()) {
      roots_.push_back(node);
      ends_.push_back(subtree_end(nodes, node));
      return;
    }
    top_.push_back(node);
    split(nodes, nodes[node].left, depth + 1);
    split(nodes, nodes[node].right, depth + 1);
  }

  int size_ = 0;
  std::vector<int> roots_, ends_, top_;  // the subtrees, their ends, the nodes above (preorder)
};

}  // namespace fdh::parallel
