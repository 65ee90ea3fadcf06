// The rule on pairs near by construction (`audit --min-distance`, docs/audit.md): a fine mesh
// has neighbours closer than D at rest (a 200x200 grid over 2 m has vertices 0.01 m apart), and
// simulators leave such pairs out of their distance. The audit leaves out of its proximity kinds
// (never out of its intersection kinds) cloth pairs within a few rings of each other in the mesh,
// and pairs already within D in the first frame.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh_parts.hpp"

namespace fdh::audit {

class NearPairs {
 public:
  NearPairs() = default;
  // The cloth's vertices within `rings` edges of each vertex (rings <= 0: none).
  NearPairs(const MeshParts& cloth, int vertices, int rings);

  // Whether some vertex of a[0, na) is within the rings of some vertex of b[0, nb).
  bool rings_near(const int* a, int na, const int* b, int nb) const;

  // A pair of primitives as one key: its contact kind (0 .. 6) and two indices (< 2^30).
  static std::uint64_t key(int kind, int a, int b) {
    return std::uint64_t(kind) << 60 | std::uint64_t(a) << 30 | std::uint64_t(b);
  }
  // The pairs within D in the first frame, once (any order, repeats allowed).
  void set_first_frame(std::vector<std::uint64_t> keys);
  bool first_frame(std::uint64_t k) const;
  long first_frame_pairs() const { return long(first_.size()); }

 private:
  std::vector<int> start_, near_;     // per vertex, sorted: near_[start_[v], start_[v + 1])
  std::vector<std::uint64_t> first_;  // sorted
};

}  // namespace fdh::audit
