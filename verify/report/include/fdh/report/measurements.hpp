// The measurements behind the report's tables and charts. Each returns its rows; the numbers
// are measured in this run, so compare rows with each other, not across machines. The *_csv
// functions give the rows as the report's data files (docs/formats.md, "report").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fdh/os/progress.hpp"
#include "fdh/query.hpp"

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

// The queries of all_families()[family] that speed_accuracy measures (and toi_speed, on the
// same queries): per_family of them from the family's own stream.
std::vector<Query> family_queries(std::size_t family, long per_family, std::uint64_t seed);

// One method's times of impact on the queries of one moving family, against the exact earliest
// contact t* (check/checker.hpp, check_time): how early its t_lo is over the contacts it found
// in time, in step units, and how often it is late.
struct ToiSpeedRow {
  std::string method, family;
  long queries = 0, contacts = 0;  // the queries it gave a time for; those with a contact
  double ns_per_query = 0;
  double early_median = 0, early_max = 0;  // t* - t_lo; 0 without a contact found in time
  long late = 0;                           // contacts missed or t_lo > t*: the step passes through
  long early = 0;  // contacts found with t* - t_lo above the width asked (kToiWidthAsked)
  long zero = 0;   // t_lo = 0 where t* > 0
  long verdict_errors = 0;
};

// The width of the enclosure every TOI measurement asks for: robust's default, 2^-30.
inline constexpr double kToiWidthAsked = 0x1p-30;

// Every method that gives a time of impact (the exact twin included) on `per_family` queries
// of every moving family (the queries of speed_accuracy). `progress` hears the families done.
std::vector<ToiSpeedRow> toi_speed(long per_family, std::uint64_t seed,
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

// For one TOI sweep (a stability sweep whose queries approach a grazing contact) and one value
// of its parameter: one TOI method's errors on its per_point queries.
struct ToiStabilityRow {
  std::string sweep;
  int parameter = 0;
  std::string method;
  long queries = 0, contacts = 0, late = 0;
  double early_median = 0, early_max = 0;  // as ToiSpeedRow's
};

// The TOI sweeps: the stability sweeps (same queries, same streams) whose contacts turn
// grazing: angle (the motion's angle to the plane 2^-p), edge (the crossing 2^-p from an edge)
// and tangency (a dip 2^-p deep: a double root in time). Every method that gives a time of
// impact, the twin aside, checked untimed. Rows run as stability's.
const std::vector<StabilitySweep>& toi_stability_sweeps();
std::vector<ToiStabilityRow> toi_stability(long per_point, std::uint64_t seed,
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

// One method at one minimum separation δ on the queries of every generator family of one kind
// (issue 30): rates against the exact twin at that δ.
struct MinDistanceSpeedRow {
  std::string method;
  int exponent = 0;  // δ = 2^-exponent times each query's own size; 0: δ = 0
  std::string kind;  // "static" or "moving"
  long queries = 0;  // the queries it answers (a method that does not answer δ > 0 has no row)
  double ns_per_query = 0, fp_rate = 0, fn_rate = 0;
};

// The exponents e of δ = 2^-e times a query's size measured, 0 standing for δ = 0: 0, 40, 20, 10.
const std::array<int, 4>& min_distance_exponents();

// Every method on `per_family` queries of every generator family (family_queries), static and
// moving apart, at each δ of min_distance_exponents(). A query's size is the largest extent of
// its points along an axis, rounded down to a power of two (so δ is exact).
std::vector<MinDistanceSpeedRow> min_distance_speed(long per_family, std::uint64_t seed,
                                                    const ProgressSink& progress = {});

// The D of the stability of the minimum separation: queries of about unit size asked at δ = D.
inline constexpr double kMinDistanceStabilityD = 0x1p-20;

// One method on the queries of one point of that stability: their least distance is exactly
// H = D·(1 + side·2^-p) by construction (side 0: H = D), so the answer is "within" iff side <= 0.
struct MinDistanceStabilityRow {
  int side = 0, p = 0;  // side -1: H below D, +1: above
  std::string method;
  long queries = 0;
  double failure_rate = 0;  // the share of its answers that are wrong
  // Where the chart draws it: side·(60 - p), so that H = D is at 0 and each side's closest
  // points lie next to it.
  int x() const { return side * (60 - p); }
};

// The p of each side: 10, 15, ..., 50.
const std::vector<int>& min_distance_stability_steps();

// `per_point` queries per point (side, p), of five configurations in turn (a point over a
// face's interior, beside an edge, beyond a corner; parallel edges; crossing edges), each at
// least H apart at every time and exactly H apart at some, their axes permuted; every method
// that answers them (the twin included) asked at δ = D.
std::vector<MinDistanceStabilityRow> min_distance_stability(long per_point, std::uint64_t seed,
                                                            const ProgressSink& progress = {});

// The data files, header line first:
//   method,family,queries,ns_per_query,fp_rate,fn_rate,kind
std::string speed_accuracy_csv(const std::vector<SpeedAccuracyRow>& rows);
//   method,family,ns_per_query,error_rate,kind
std::string pareto_csv(const std::vector<SpeedAccuracyRow>& front);
//   sweep,parameter,method,failure_rate
std::string stability_csv(const std::vector<StabilityRow>& rows);
//   method,family,queries,contacts,ns_per_query,early_median,early_max,late,early,zero,
//   verdict_errors
std::string toi_speed_csv(const std::vector<ToiSpeedRow>& rows);
//   sweep,parameter,method,queries,contacts,late,early_median,early_max
std::string toi_stability_csv(const std::vector<ToiStabilityRow>& rows);
//   k,grid,cloth_triangles,obstacle_triangles,build_ms,refit_ms,traverse_ms,candidate_pairs,
// with a blank line between grids (gnuplot draws one line per block).
std::string kdop_tree_csv(const std::vector<KdopTreeRow>& rows);
//   method,delta,kind,queries,ns_per_query,fp_rate,fn_rate (delta: 0 or 2^-e, times the size)
std::string min_distance_speed_csv(const std::vector<MinDistanceSpeedRow>& rows);
//   side,p,x,method,queries,failure_rate
std::string min_distance_stability_csv(const std::vector<MinDistanceStabilityRow>& rows);

}  // namespace fdh::verify
