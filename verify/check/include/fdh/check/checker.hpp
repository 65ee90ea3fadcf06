// The one checker: every "fast equals exact" in the suite goes through here, as CGAL's
// Kernel_checker runs two kernels side by side. A method's answer is compared with the exact
// twin of its decision under the method's promise (registry.hpp); certify, `classify --check`,
// the scene runs, fuzz and the tests all ask this file, and nothing else compares.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

// Whether `said` keeps `promise` where the twin says `twin`.
bool keeps_promise(Promise promise, bool said, bool twin);

// What the checker found for one query.
struct Verdicts {
  bool said = false, twin = false;
  bool kept = true;  // said keeps the method's promise
  // No answer: a plug-in's call past --plugin-timeout, abandoned (NoAnswer; `said` is then
  // meaningless): a broken promise for a method that promises anything.
  bool no_answer = false;
  double limit = 0;  // with no_answer: the time limit it passed, seconds
  bool agree() const { return !no_answer && said == twin; }
};

// One method against the twin on one query it applies to.
Verdicts check(const Method& m, const Query& q);
// The same with the twin's verdict already known (several methods on one query).
Verdicts check(const Method& m, const Query& q, bool twin);
// The method's test for decision d against d's twin (a static query asked as a CCD query, say);
// a method without a test for d keeps its promise trivially (said = twin).
Verdicts check(const Method& m, const Query& q, Decision d);
// No verdict: m's call did not return within --plugin-timeout (NoAnswer, which check lets
// through: only certify counts it, as a broken promise of a promised method).
Verdicts unanswered(const Method& m, const NoAnswer& e, bool twin);
// A verdict the method already gave elsewhere (the simulator's narrow phase) against the twin.
Verdicts check_given(const Method& m, const Query& q, bool said);

// The twin against a file's truth (a verdict, or nullopt where the file gives none): nullopt
// without a truth, else whether they agree.
std::optional<bool> twin_matches_truth(std::optional<bool> truth, bool twin);

// A count of checks and of broken promises, with the first few broken cases kept.
struct CheckTally {
  long checked = 0, broken = 0;
  long filter_decided = 0;                // checked queries the method's float filter decided alone
  std::vector<std::size_t> first_broken;  // indices into the caller's sequence, at most `keep`

  void add(bool kept, std::size_t index, std::size_t keep = 16);
};

// One method against the twin over a sequence of queries, with the twin's verdicts given
// (twin[i] for queries[i]); queries the method does not apply to are skipped.
CheckTally check_all(const Method& m, const std::vector<Query>& queries,
                     const std::vector<char>& twin);

// A k-DOP method's box of `n` points: the first slab (in the order of m.directions) where it
// fails to contain the exact FDH along them, or -1. Conservative methods must return -1. Throws
// std::invalid_argument for a method without k / 2 directions.
int check_box(const BoxMethod& m, const Vec3* pts, std::size_t n);

// A k-DOP method's overlap test on the boxes it builds of two point sets, against the exact
// FDHs along m.directions. Conservative methods must not say "no" where the exact FDHs
// overlap.
Verdicts check_overlap(const BoxMethod& m, const std::vector<Vec3>& a, const std::vector<Vec3>& b);

// A broad phase (tree traversal) against the exact overlapping pairs: the pairs it culled
// although their exact boxes overlap (a conservative broad phase culls none).
std::vector<std::pair<int, int>> culled_pairs(std::vector<std::pair<int, int>> found,
                                              const std::vector<std::pair<int, int>>& exact);

// Which way a verdict differs from the twin's.
enum class Disagreement {
  None,
  Miss,        // "no" where the twin says "hit" (a false negative)
  FalseAlarm,  // "hit" where the twin says "no" (a false positive)
};
Disagreement disagreement_of(bool said, bool twin);

// What a promise makes of a finding against the twin: nothing found, a broken promise, a
// disagreement the promise allows (a conservative method's false alarm, a never-late time's
// earliness), or one that no promise speaks of (a method that promises nothing).
enum class Judgement { Kept, Broken, Allowed, Unpromised };
Judgement judge(Promise p, bool said, bool twin);

// The words of a judgement, for classify, replay and the certificate: "(breaks CONSERVATIVE)"
// (a verdict's promise in capitals, as fdh/plugin.h names it), "(allowed: conservative)",
// "(breaks never-late)", "(allowed: never-late)", "(no promise)"; "" for Kept.
std::string judgement_words(Judgement j, Promise p);
std::string judgement_words(Judgement j, TimePromise p);

// One verdict against the twin's, judged by m's promise: "aabb gives a false alarm at FILE:LINE
// (allowed: conservative)", "robust misses a hit (breaks EXACT)", "float-cubic answers no where
// exact says hit (no promise)"; "" where they agree. `where` ("" for none) follows " at ".
// classify, replay and the certificate all take their words from here.
std::string verdict_words(const Method& m, bool said, bool twin, const std::string& where = "");

// The disagreements of one method with the twin, by direction, and what its promise makes of
// them (broken + allowed = misses + false_alarms for a promised method; 0 and 0 for one without
// a promise).
struct DisagreementTally {
  long misses = 0, false_alarms = 0;
  long broken = 0, allowed = 0;
  void add(Promise p, bool said, bool twin);
  void merge(const DisagreementTally& o);
};

// "robust says hit, the exact twin says no: gives a false alarm (breaks EXACT)": the words of a
// checked verdict, for messages and the certificate.
std::string describe(const Method& m, const Verdicts& v);

// The exact earliest contact of a query, once for all the methods checked on it: the verdict
// and t* rounded to a double (for how early a time is; late or not is decided exactly).
struct TimeTwin {
  bool hit = false;
  double t_star = 1;  // t* to within 2^-52 (exact::ccd), 1 without a hit
};
TimeTwin time_twin(const Query& q);

// What the checker found for one method's time of impact on one query (the TOI decisions).
struct TimeCheck {
  Toi said;
  TimeTwin twin;
  double width = kDefaultToiWidth;  // the width asked
  bool verdict_error = false;       // said.hit differs from the exact verdict
  bool late = false;       // a contact missed, or t_lo > t* (exactly): breaks either promise
  bool enclosed = true;    // with both hits: t_lo <= t* <= t_hi, exactly
  bool too_wide = false;   // with a hit said: t_hi - t_lo above the width asked
  bool zero = false;       // t_lo == 0 said where 0 < t*
  double early = 0;        // with both hits and not late: t* - t_lo, in step units (>= 0)
  bool kept = true;        // the method's TimePromise is kept
  bool garbage = false;    // not a time: not 0 <= t_lo <= t_hi <= 1 with a hit: breaks either
  bool no_answer = false;  // no answer within --plugin-timeout (NoAnswer): breaks either
  double limit = 0;        // with no_answer: the time limit it passed, seconds
};

// t_hi = +inf: "no upper bound", which a never-late (lower-bound) method may say
// (FDH_TIME_NO_UPPER_BOUND, fdh/plugin.h); its enclosure then means nothing.
bool no_upper_bound(const Toi& t);

// How early a time of impact may be (t* - t_lo, step units) before fuzz --toi and replay --toi
// call it a finding: a solver that moves to a time a tenth of the step early stalls.
inline constexpr double kDefaultToiTolerance = 0.1;

// Whether the findings of `c` keep `promise` (registry.hpp TimePromise).
bool keeps_time_promise(TimePromise promise, const TimeCheck& c);

// One method's time of impact, asked at `width`, against the exact twin; the twin's answer
// given or computed. The method must give one for q's TOI decision (Method::gives_toi).
TimeCheck check_time(const Method& m, const Query& q, double width, const TimeTwin& twin);
TimeCheck check_time(const Method& m, const Query& q, double width);
// No time: as unanswered, for a time of impact.
TimeCheck unanswered_time(const Method& m, const NoAnswer& e, double width, const TimeTwin& twin);
// A time the method already gave (classify's timed runs, a plug-in's saved answer).
TimeCheck check_time_given(const Method& m, const Query& q, double width, const Toi& said,
                           const TimeTwin& twin);

// The counts of the TOI checks of one method, over many queries.
struct TimeTally {
  long checked = 0, contacts = 0;  // queries checked; those with an exact contact
  long verdict_errors = 0, late = 0, zero = 0, not_enclosed = 0, too_wide = 0, garbage = 0;
  long no_answer = 0;                     // calls past --plugin-timeout (each a broken promise)
  long broken = 0;                        // checks that broke the method's TimePromise
  std::vector<double> early;              // t* - t_lo of every contact found in time, step units
  std::vector<std::size_t> first_broken;  // indices into the caller's sequence, at most `keep`

  void add(const TimeCheck& c, std::size_t index, std::size_t keep = 16);
  void merge(const TimeTally& other, std::size_t offset);  // other's indices shifted by offset
  double early_max() const;                                // 0 without contacts
  double early_median() const;                             // the lower median; 0 without contacts
};

// "float-cubic's TOI is late: t_lo = 0x1.8p-1 > t* = 0.74...": the words of a time check that
// found something, for messages and case files ("" when it found nothing).
std::string describe(const Method& m, const TimeCheck& c);

// What m's time promise makes of c: Kept when c found nothing (describe says ""), Broken when
// it breaks the promise, Allowed when the promise permits what was found (a never-late time's
// earliness, an enclosure's), Unpromised for a method without a time promise.
Judgement judge(const Method& m, const TimeCheck& c);
// describe(m, c) with its judgement: "late-toi's TOI is late: t_lo = 1 > t* ~ 0.5 (breaks
// never-late)", "robust's TOI is early by 1e-10 of the step, t* ~ 0.5 (allowed:
// exact-enclosure)"; "" when c found nothing.
std::string judged_time_words(const Method& m, const TimeCheck& c);

}  // namespace fdh::verify
