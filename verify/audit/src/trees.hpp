// The audit's broad phase: the cloth's FDH tree (fdh::Bvh<K>, built once from the first frame,
// refit per step and swept over it) against itself with normal-cone culling, and against the
// obstacles' tree (swept too while the obstacles move). It hands each leaf pair to the narrow
// phase (narrow_phase.hpp), on every core, in chunks fixed by the work's sizes alone.
#pragma once

#include <memory>
#include <vector>

#include "narrow_phase.hpp"

namespace fdh::audit {

class Trees {
 public:
  virtual ~Trees() = default;
  // The pass's leaf pairs through the narrow phase: the parts in an order fixed by the trees
  // and the positions alone.
  virtual std::vector<Part> run(const Pass& pass) = 0;
  // The cloth's tree nodes found flat by the last run (for tests and statistics).
  virtual long flat_nodes() const = 0;
};

// k from Options::k (6, 14, 18 or 26; std::invalid_argument otherwise); x and y: the first
// frame's cloth and obstacle positions, which the trees are built over.
std::unique_ptr<Trees> make_trees(int k, const MeshParts& cloth, const MeshParts& obstacle,
                                  const std::vector<Vec3>& x, const std::vector<Vec3>& y);

}  // namespace fdh::audit
