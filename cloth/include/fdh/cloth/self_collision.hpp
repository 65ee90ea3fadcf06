// The cloth against itself (optional, scene keyword `self_collision on`): after the obstacle
// response, every moving vertex–triangle and edge–edge pair of the cloth's own primitives that
// share no particle is tested over the step with `robust` CCD (fdh/ccd/robust.hpp), the
// candidates coming from FDH trees over the swept particles, triangles and edges.
//
// Response: the particles of every pair that touches go back to where the step started, at
// rest (an inelastic stop). The start of a step is free of self-contact, so this can only
// remove contacts, but it can create new ones with neighbours that kept moving: the test runs
// again, up to four rounds, and if contacts remain the whole cloth goes back to the start of
// the step. Exact CCD (no false negatives) and an intersection-free start make the end of every
// step intersection-free.
#pragma once

#include <memory>
#include <vector>

#include "fdh/ccd/robust.hpp"
#include "fdh/cloth/cloth.hpp"

namespace fdh::cloth {

class SelfCollision {
 public:
  // k: the FDH's k. exact: robust's fallback (fdh::exact::ccd_hit in this project).
  SelfCollision(const Cloth& cloth, int k, CcdTest exact);
  ~SelfCollision();

  struct Result {
    long queries = 0;  // CCD queries run
    long hits = 0;     // of them, contacts
    bool stopped_all = false;
  };

  // Makes the step from x0 to x free of self-contact, changing x and v where needed.
  Result resolve(const Cloth& cloth, const std::vector<Vec3>& x0, std::vector<Vec3>& x,
                 std::vector<Vec3>& v);

 private:
  struct Trees;
  template <int K>
  struct TreesK;
  std::unique_ptr<Trees> trees_;
  CcdTest exact_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<char> stop_;
};

}  // namespace fdh::cloth
