// The step's loops on every core the run allows (oneTBB), with results that do not depend on the
// thread count: work is cut into chunks fixed by the problem size alone, each chunk writes only
// its own outputs, and whatever is gathered from chunks is merged in chunk order.
#pragma once

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

// The subtrees of a binary tree at depth 6 (or the leaves above it) into `roots`, and the nodes
// above them into `top`, in preorder: 64 subtrees, work for every core in a bottom-up pass with
// little left on top. Node: leaf(), left, right.
template <class Node>
void split_subtrees(const std::vector<Node>& nodes, int node, std::vector<int>& roots,
                    std::vector<int>& top, int depth = 0) {
  const Node& n = nodes[node];
  if (depth == 6 || n.leaf()) {
    roots.push_back(node);
    return;
  }
  top.push_back(node);
  split_subtrees(nodes, n.left, roots, top, depth + 1);
  split_subtrees(nodes, n.right, roots, top, depth + 1);
}

}  // namespace fdh::cloth
