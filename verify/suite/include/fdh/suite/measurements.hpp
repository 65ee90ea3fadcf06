// The measurements behind the report's charts. Each returns CSV text (header line first); the
// numbers are measured in this run, so compare rows with each other, not across machines.
#pragma once

#include <cstdint>
#include <string>

namespace fdh::verify {

// method,family,queries,ns_per_query,fp_rate,fn_rate: every method on `per_family` queries of
// every generator family, rates against exact.
std::string speed_accuracy_csv(long per_family, std::uint64_t seed);

// The lower-left envelope of speed_accuracy_csv: method,family,ns_per_query,error_rate for the
// points no other point beats in both time and error (fp + fn) rate.
std::string pareto_csv(const std::string& speed_accuracy);

// sweep,parameter,method,failure_rate: for each sweep, the share of `per_point` queries each
// method gets wrong, as one parameter goes to its degenerate limit:
//   angle      the motion's angle to the plane is 2^-p (p = 0..60)
//   edge       the path crosses the plane 2^-p from an edge, inside or out (p = 0..64)
//   magnitude  the whole query moved 2^p from the origin (p = 0..40)
//   aspect     the triangle's height over its base is 2^-p (p = 0..60)
std::string stability_csv(long per_point, std::uint64_t seed);

// k,grid,cloth_triangles,obstacle_triangles,build_ms,refit_ms,traverse_ms,candidate_pairs:
// a cloth grid of n×n particles draped over a triangulated sphere, the cloth tree swept over
// one step, for k = 6, 14, 18, 26.
std::string kdop_tree_csv(int grid);

}  // namespace fdh::verify
