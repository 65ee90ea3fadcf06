// The step's loops on every core the run allows (oneTBB), with results that do not depend on the
// thread count: work is cut into chunks fixed by the problem size alone, each chunk writes only
// its own outputs, and whatever is gathered from chunks is merged in chunk order.
#pragma once

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <utility>
#include <vector>

namespace fdh::cloth {

// f(begin, end) for consecutive chunks of [0, n) of `grain` items (the last may be shorter).
template <class F>
void for_chunks(int n, int grain, const F& f) {
  const int chunks = (n + grain - 1) / grain;
  if (chunks <= 1) {
    if (n > 0) f(0, n);
    return;
  }
  tbb::parallel_for(
      tbb::blocked_range<int>(0, chunks, 1),
      [&](const tbb::blocked_range<int>& r) {
        for (int c = r.begin(); c < r.end(); ++c) f(c * grain, std::min(n, (c + 1) * grain));
      },
      tbb::simple_partitioner());
}

// Runs f(c, out[c]) for chunks c = 0 .. chunks - 1 in parallel, then appends the chunks' outputs
// to `all` in chunk order: the same `all` for any thread count.
template <class T, class F>
void gather_chunks(int chunks, std::vector<std::vector<T>>& out, std::vector<T>& all, const F& f) {
  out.resize(std::max(chunks, 0));
  tbb::parallel_for(
      tbb::blocked_range<int>(0, chunks, 1),
      [&](const tbb::blocked_range<int>& r) {
        for (int c = r.begin(); c < r.end(); ++c) {
          out[c].clear();
          f(c, out[c]);
        }
      },
      tbb::simple_partitioner());
  for (const auto& part : out) all.insert(all.end(), part.begin(), part.end());
}

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

}  // namespace fdh::cloth
