// The measurements behind the report's tables and charts. Each returns its rows; the numbers
// are measured in this run, so compare rows with each other, not across machines. The *_csv
// functions give the rows as the report's data files (docs/formats.md, "report").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fdh/os/progress.hpp"

namespace fdh::verify {

// One method on the queries of one generator family, rates against the exact twin.
struct SpeedAccuracyRow {
  std::string method, family;
  long queries = 0;
  double ns_per_query = 0, fp_rate = 0, fn_rate = 0;
  std::string kind = "static";  // the family's queries: "static" or "moving"
  double error_rate() const { return fp_rate + fn_rate; }
};

// Every method of the registry on `per_family` queries of every generator family, static and
// moving; a method is measured on the queries it applies to, and has no row where it applies
// to none (the paper's readings have no moving rows).
// `progress` hears the families done ("speed against accuracy").
std::vector<SpeedAccuracyRow> speed_accuracy(long per_family, std::uint64_t seed,
                                             const ProgressSink& progress = {});

// The lower-left envelope of `rows`: the points no other point beats in both time and error
// rate, fastest first.
std::vector<SpeedAccuracyRow> pareto_front(const std::vector<SpeedAccuracyRow>& rows);
// The front of each kind of `rows` on its own (static, then moving): a moving query costs
// another order of time, so one front over both would hide the static one.
std::vector<SpeedAccuracyRow> pareto_fronts(const std::vector<SpeedAccuracyRow>& rows);

// For one sweep and one value of its parameter: the share of queries a method gets wrong.
struct StabilityRow {
  std::string sweep;
  int parameter = 0;
  std::string method;
  double failure_rate = 0;
};

// A sweep of the stability measurement: p runs 0..last; `axis` says what p is, for charts.
struct StabilitySweep {
  const char* name;
  int last;
  const char* axis;
};
const std::vector<StabilitySweep>& stability_sweeps();

// For each sweep, the share of `per_point` queries each method (the twin aside) gets wrong, as
// one parameter goes to its degenerate limit (a method that applies to none of a sweep's
// queries has no rows there):
//   angle      the motion's angle to the plane is 2^-p (p = 0..60)
//   edge       the path crosses the plane 2^-p from an edge, inside or out (p = 0..64)
//   magnitude  the whole query moved 2^p from the origin (p = 0..40)
//   aspect     the triangle's height over its base is 2^-p (p = 0..60)
//   tangency   (moving) a point meets a tilting triangle's plane at a double root: it dips
//              2^-p through the face and back, or stays 2^-p short of it (p = 0..56)
//   coplanar   (moving) all four points stay within 2^-p of one plane while the point sweeps
//              across the triangle's edge (p = 0..60)
// Rows run sweep by sweep, and within a sweep method by method, so each curve is contiguous.
// `tick(done, total)` after each sweep.
std::vector<StabilityRow> stability(long per_point, std::uint64_t seed,
                                    const ProgressSink& progress = {});

// The FDH tree of one k on a cloth over a sphere: medians of 20 runs.
struct KdopTreeRow {
  int k = 0, grid = 0;
  long cloth_triangles = 0, obstacle_triangles = 0;
  double build_ms = 0, refit_ms = 0, traverse_ms = 0;
  long candidate_pairs = 0;
};

// A cloth grid of n×n particles draped over a triangulated sphere, the cloth tree swept over
// one step, for k = 6, 14, 18, 26.
std::vector<KdopTreeRow> kdop_tree(int grid);

// The data files, header line first:
//   method,family,queries,ns_per_query,fp_rate,fn_rate,kind
std::string speed_accuracy_csv(const std::vector<SpeedAccuracyRow>& rows);
//   method,family,ns_per_query,error_rate,kind
std::string pareto_csv(const std::vector<SpeedAccuracyRow>& front);
//   sweep,parameter,method,failure_rate
std::string stability_csv(const std::vector<StabilityRow>& rows);
//   k,grid,cloth_triangles,obstacle_triangles,build_ms,refit_ms,traverse_ms,candidate_pairs,
// with a blank line between grids (gnuplot draws one line per block).
std::string kdop_tree_csv(const std::vector<KdopTreeRow>& rows);

}  // namespace fdh::verify
