// The registry of point–triangle methods. The CLI, the tests and the benchmarks iterate over it;
// adding a method is one entry here.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fdh/point_triangle/robust.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

struct Method {
  std::string name;
  std::string summary;
  // The verdict: true = hit. Defined on static vertex-face queries always, and on moving
  // triangles and edge-edge queries too when `moving` is set; elsewhere the method is "n/a".
  std::function<bool(const Query&)> hit;
  bool moving = false;
  // The static vertex-face test as a plain function (never gated), for the cloth simulator's
  // narrow phase; null for methods that are not one (float-cubic).
  PointTriangleTest point_triangle = nullptr;
  bool applies_to(const Query& q) const { return moving || q.is_static_vf(); }
};

// exact, robust, float-cubic, paper-literal, paper-intended, linear-system, in that order. With
// gate_k > 0 the paper methods say "hit" only when the k-DOP of the particle's sweep overlaps the
// triangle's k-DOP, as they would inside the FDH tree.
std::vector<Method> all_methods(int gate_k = 0);

// The named subset, in the order given. Throws std::invalid_argument naming an unknown method.
std::vector<Method> select_methods(const std::vector<std::string>& names, int gate_k = 0);

}  // namespace fdh::verify
