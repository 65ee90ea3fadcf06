// The registry: every method the suite runs, what it decides, its function, and the exact twin
// of that decision (reference/). The CLI, the checker, certify, the scene runs, the benchmarks
// and the tests iterate over it; nobody looks a method up to compare against by its name.
// Adding a method is one file (its function, in fast/ or a plug-in) and one entry in
// registry.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fdh/ccd/toi.hpp"
#include "fdh/filtered.hpp"
#include "fdh/kdop.hpp"
#include "fdh/point_triangle/robust.hpp"
#include "fdh/query.hpp"
#include "fdh/vec3.hpp"

namespace fdh::verify {

// What a method decides. Each decision has one exact twin.
enum class Decision {
  PointTriangle,  // static vertex-face: the segment BB' against the still triangle DEF
  VertexFaceCcd,  // a moving point against a moving triangle over the step
  EdgeEdgeCcd,    // two moving edges over the step
  KdopBuild,      // the k-DOP of a point set: must contain the exact FDH of the points
  KdopOverlap,    // do the k-DOPs of two point sets overlap: must not miss an exact overlap
  VertexFaceToi,  // the time of impact of a moving point and triangle (fdh/ccd/toi.hpp)
  EdgeEdgeToi,    // the time of impact of two moving edges
};
inline constexpr std::array<Decision, 3> kQueryDecisions = {
    Decision::PointTriangle, Decision::VertexFaceCcd, Decision::EdgeEdgeCcd};
const char* to_string(Decision d);  // "point-triangle", "vertex-face-ccd", ...
inline constexpr std::array<Decision, 2> kToiDecisions = {Decision::VertexFaceToi,
                                                          Decision::EdgeEdgeToi};
// The query decision a query asks for: PointTriangle when the triangle stands still.
Decision decision_of(const Query& q);
// The TOI decision of a query: VertexFaceToi for any vertex-face query (a still triangle is a
// moving one that stays), EdgeEdgeToi for edge-edge.
Decision toi_decision_of(const Query& q);
// Its index in Method::toi: 0 for VertexFaceToi, 1 for EdgeEdgeToi.
std::size_t toi_index(Decision d);

// What the checker holds a method to, against the exact twin of its decision.
enum class Promise {
  Exact,         // the twin's verdict on every input
  Conservative,  // never "no" where the twin says "yes" (bounding volumes)
  None,          // measured, not promised: known to fail (the paper's readings, float-cubic)
};
const char* to_string(Promise p);

// What the checker holds a method's time of impact to, against the exact earliest contact t*
// (reference/ exact::compare_with_toi). A late time (t_lo > t*, or a contact missed) breaks both.
enum class TimePromise {
  Enclosure,  // the exact verdict, t_lo <= t* <= t_hi, and t_hi - t_lo <= the width asked
  NeverLate,  // no contact missed, and t_lo <= t* (any hit where there is none is allowed)
  None,       // measured, not promised (float-cubic)
};
const char* to_string(TimePromise p);  // "exact-enclosure", "never-late", "none"

// A method that gave no answer on a query: a plug-in call past --plugin-timeout, abandoned
// (docs/plugins.md). what() names the plug-in, the function and the query; the checker counts
// it as a broken promise on that query ("no answer in T s") and the run goes on.
struct NoAnswer : std::runtime_error {
  NoAnswer(const std::string& what, std::string method_name, double limit)
      : std::runtime_error(what), method(std::move(method_name)), seconds(limit) {}
  std::string method;
  double seconds;  // the limit it passed
};

using QueryTest = std::function<bool(const Query&)>;
using QueryFilter = std::function<Filtered(const Query&)>;
// A time of impact with an enclosure no wider than `width` asked (a method may ignore it).
using QueryToi = std::function<Toi(const Query&, double width)>;

// A method of the query decisions: a row of `classify`.
struct Method {
  std::string name, summary;
  Promise promise = Promise::None;
  // The verdict per query decision (indexed by Decision), empty where the method makes none
  // (the query is "n/a" for it).
  std::array<QueryTest, 3> test;
  // Its floating-point filter per decision, where it has one: certify counts the queries the
  // filter decided alone.
  std::array<QueryFilter, 3> filter;
  // The static test as a plain function (never gated), for the cloth's narrow phase; null for
  // methods that are not one.
  PointTriangleTest point_triangle = nullptr;
  // True for the entry that is the exact twin itself (listed so that tables show it).
  bool is_twin = false;
  // Its functions are called from the calling thread only, one call at a time: a plug-in's
  // (docs/plugins.md promises no more). The built-in methods are safe from any thread.
  bool one_thread = false;
  // Its time functions' contact is its verdict (a plug-in's FDH_PLUGIN_TOI_GIVES_VERDICT):
  // classify --toi asks the time alone, once per query.
  bool verdict_from_toi = false;
  // Its time of impact per TOI decision (indexed by toi_index), empty where it gives none, and
  // what that time promises.
  std::array<QueryToi, 2> toi{};
  TimePromise time_promise = TimePromise::None;

  // It answers the minimum-separation question (Query::min_distance > 0) too; a method that does
  // not is "n/a" on every query with δ > 0 (docs/methods.md, "Minimum separation").
  bool answers_min_distance = false;

  bool applies_to(const Query& q) const {
    return bool(test[std::size_t(decision_of(q))]) && (q.min_distance == 0 || answers_min_distance);
  }
  bool hit(const Query& q) const { return test[std::size_t(decision_of(q))](q); }
  // A time for q's TOI decision, and for q's δ (as applies_to).
  bool gives_toi(const Query& q) const {
    return bool(toi[toi_index(toi_decision_of(q))]) &&
           (q.min_distance == 0 || answers_min_distance);
  }
  Toi time_of_impact(const Query& q, double width) const {
    return toi[toi_index(toi_decision_of(q))](q, width);
  }
};

// The exact twin of a query decision: its verdict (reference/), for the query's own decision or
// for a given one (a static query is also a moving one whose triangle stays: VertexFaceCcd).
bool twin_hit(const Query& q);
bool twin_hit(const Query& q, Decision d);
// The exact twin of the TOI decisions: the exact verdict and an enclosure of t* no wider than
// `width` (exact::ccd_toi over the whole step).
Toi twin_toi(const Query& q, double width);

// A k-DOP method of a fixed k: builds a box (lo, hi per slab) and decides overlap of two boxes.
// Slab s has the integer direction directions[s] (k = 2 × directions.size()), in the method's
// own order: fdh::Kdop<k>'s for the project's boxes and a plug-in's (kdop_directions below), the
// library's own for a peer (verify/peers/). The checker takes them as given.
struct BoxMethod {
  std::string name, summary;
  int k = 0;
  std::vector<Direction> directions;
  Promise promise = Promise::Conservative;
  // fast/'s FDH tree is made of these boxes: certify checks its traversal too.
  bool builds_tree = false;
  std::function<void(const Vec3* pts, std::size_t n, double* lo, double* hi)> build;
  std::function<bool(const double* lo_a, const double* hi_a, const double* lo_b,
                     const double* hi_b)>
      overlap;
  bool one_thread = false;  // as Method::one_thread
};

// fdh::Kdop<k>'s slab directions, in its order (fast/kdop.hpp): k / 2 of them.
std::vector<Direction> kdop_directions(int k);

// Every query method: the twin first, then robust, float-cubic, paper-literal,
// paper-intended, linear-system; then the added ones (add_methods). With gate_k > 0 the methods
// that test no bounding volume of their own say "hit" only when the k-DOP of the particle's sweep
// overlaps the triangle's, as they would inside the FDH tree. Throws std::invalid_argument for a
// bad gate_k.
std::vector<Method> all_methods(int gate_k = 0);

// The methods the checker holds to a promise (Exact or Conservative), the twin itself left out.
std::vector<Method> promised_methods(int gate_k = 0);
// The methods whose time of impact keeps a promise (Enclosure or NeverLate), the twin left out.
std::vector<Method> time_promised_methods();
// The methods that give a time of impact at all, the twin first.
std::vector<Method> toi_methods();

// The named subset, in the order given. Throws std::invalid_argument naming an unknown method
// and listing the known ones.
std::vector<Method> select_methods(const std::vector<std::string>& names, int gate_k = 0);

// The methods that can run as the cloth's narrow phase (point_triangle set), and one by name
// (std::invalid_argument listing the known ones when unknown).
std::vector<std::string> narrow_phase_names();
// The names of all_methods(), in its order.
std::vector<std::string> method_names();
PointTriangleTest narrow_phase_named(const std::string& name);

// The k-DOP methods for each certified k (6, 14, 18, 26), then the added ones.
std::vector<BoxMethod> all_box_methods();
inline constexpr std::array<int, 4> kCertifiedK = {6, 14, 18, 26};

// Methods added at run time (plug-ins, verify/plugin/): all_methods() and all_box_methods()
// return them after the built-in ones, for this process and the workers it forks. A name that
// is already taken (query methods and k-DOP methods of one k are separate) throws
// std::invalid_argument naming it; nothing is added then.
void add_methods(std::vector<Method> methods, std::vector<BoxMethod> boxes);
// Forgets every added method (the end of one command run, in-process).
void remove_added_methods();

// Whether every registered method may be called from several threads at once (no plug-in's
// one_thread method is registered): the suite's loops then run on every core (parallel.hpp).
// add_methods and remove_added_methods must not run while anything else uses the registry;
// every other function here may be called from several threads at once.
bool registry_thread_safe();

}  // namespace fdh::verify
