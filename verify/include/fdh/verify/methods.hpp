// The registry of point–triangle methods. The CLI, the tests and the benchmarks iterate over it;
// adding a method is one entry here.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fdh/query.hpp"

namespace fdh::verify {

struct Method {
  std::string name;
  std::string summary;
  // The verdict on a static vertex-face query: true = hit.
  std::function<bool(const Query&)> hit;
};

// exact, robust, paper-literal, paper-intended, linear-system, in that order. With gate_k > 0
// the paper methods say "hit" only when the k-DOP of the particle's sweep overlaps the
// triangle's k-DOP, as they would inside the FDH tree.
std::vector<Method> all_methods(int gate_k = 0);

// The named subset, in the order given. Throws std::invalid_argument naming an unknown method.
std::vector<Method> select_methods(const std::vector<std::string>& names, int gate_k = 0);

}  // namespace fdh::verify
