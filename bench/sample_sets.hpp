// The benchmark sample's queries by set, for the benchmarks that time it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fdh/query.hpp"

namespace fdh::bench {

// Queries of each set of the build's FDH_CCD_SAMPLE (<set>/<vertex-face|edge-edge>/*.csv), in
// file order; empty without a sample.
std::map<std::string, std::vector<Query>> sample_sets();

}  // namespace fdh::bench
