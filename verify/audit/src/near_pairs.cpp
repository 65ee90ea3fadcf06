#include "near_pairs.hpp"

#include <algorithm>

namespace fdh::audit {

NearPairs::NearPairs(const MeshParts& cloth, int vertices, int rings) {
  if (rings <= 0) return;
  // The mesh's graph, then a breadth-first search `rings` deep from every vertex.
  std::vector<std::vector<int>> next(static_cast<std::size_t>(vertices));
  for (const Edge& e : cloth.edges) next[e[0]].push_back(e[1]), next[e[1]].push_back(e[0]);
  std::vector<int> depth(std::size_t(vertices), -1), seen;
  start_.assign(std::size_t(vertices) + 1, 0);
  for (int v = 0; v < vertices; ++v) {
    seen.assign(1, v);
    depth[v] = 0;
    for (std::size_t i = 0; i < seen.size(); ++i) {
      const int u = seen[i];
      if (depth[u] == rings) continue;
      for (const int w : next[u])
        if (depth[w] < 0) depth[w] = depth[u] + 1, seen.push_back(w);
    }
    for (const int u : seen) depth[u] = -1;
    std::sort(seen.begin(), seen.end());
    near_.insert(near_.end(), seen.begin(), seen.end());
    start_[std::size_t(v) + 1] = int(near_.size());
  }
}

bool NearPairs::rings_near(const int* a, int na, const int* b, int nb) const {
  if (start_.empty()) return false;
  for (int i = 0; i < na; ++i) {
    const int* lo = near_.data() + start_[a[i]];
    const int* hi = near_.data() + start_[a[i] + 1];
    for (int j = 0; j < nb; ++j)
      if (std::binary_search(lo, hi, b[j])) return true;
  }
  return false;
}

void NearPairs::set_first_frame(std::vector<std::uint64_t> keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  first_ = std::move(keys);
}

bool NearPairs::first_frame(std::uint64_t k) const {
  return std::binary_search(first_.begin(), first_.end(), k);
}

}  // namespace fdh::audit
