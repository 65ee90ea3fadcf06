// The one checker (fdh/check/checker.hpp): what each promise allows, and that it catches a
// method that breaks its promise, on hand-made cases whose truth is known.
#include "fdh/check/checker.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fdh::verify {
namespace {

// A vertical segment through the middle of the unit triangle in z = 0: a hit.
Query crossing() {
  Query q;
  q.x = {Vec3{0.25, 0.25, 1},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
         Vec3{0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  return q;
}

// The same segment beside the triangle: a miss.
Query passing() {
  Query q = crossing();
  q.x[0].x = q.x[4].x = 2;
  return q;
}

Method constant(bool verdict, Promise promise) {
  Method m;
  m.name = verdict ? "always-hit" : "never-hit";
  m.promise = promise;
  for (QueryTest& t : m.test) t = [verdict](const Query&) { return verdict; };
  return m;
}

TEST(Checker, PromisesAllowWhatTheySay) {
  EXPECT_TRUE(keeps_promise(Promise::Exact, true, true));
  EXPECT_FALSE(keeps_promise(Promise::Exact, true, false));
  EXPECT_FALSE(keeps_promise(Promise::Exact, false, true));
  EXPECT_TRUE(keeps_promise(Promise::Conservative, true, false));   // a false alarm is allowed
  EXPECT_FALSE(keeps_promise(Promise::Conservative, false, true));  // a miss is not
  EXPECT_TRUE(keeps_promise(Promise::None, false, true));
}

TEST(Checker, TheTwinDecidesTheHandMadeCases) {
  EXPECT_TRUE(twin_hit(crossing()));
  EXPECT_FALSE(twin_hit(passing()));
  Query moving = crossing();
  moving.x[5].z = moving.x[6].z = moving.x[7].z = 0.5;  // the triangle rises to meet it
  EXPECT_EQ(decision_of(moving), Decision::VertexFaceCcd);
  EXPECT_TRUE(twin_hit(moving));
}

TEST(Checker, CatchesABrokenPromise) {
  const Method liar = constant(false, Promise::Exact);
  const Verdicts v = check(liar, crossing());
  EXPECT_FALSE(v.said);
  EXPECT_TRUE(v.twin);
  EXPECT_FALSE(v.kept);
  EXPECT_EQ(describe(liar, v),
            "never-hit says no, the exact twin says hit: misses a hit (breaks EXACT)");
  EXPECT_TRUE(check(constant(true, Promise::Conservative), passing()).kept);
  EXPECT_FALSE(check(constant(false, Promise::Conservative), crossing()).kept);
}

// Each disagreement is named by its direction and judged by the promise: a miss breaks
// CONSERVATIVE, a false alarm is allowed by it, both break EXACT, and without a promise neither
// is judged.
TEST(Checker, DisagreementsAreJudgedByThePromise) {
  EXPECT_EQ(disagreement_of(false, true), Disagreement::Miss);
  EXPECT_EQ(disagreement_of(true, false), Disagreement::FalseAlarm);
  EXPECT_EQ(disagreement_of(true, true), Disagreement::None);
  EXPECT_EQ(judge(Promise::Conservative, false, true), Judgement::Broken);
  EXPECT_EQ(judge(Promise::Conservative, true, false), Judgement::Allowed);
  EXPECT_EQ(judge(Promise::Exact, true, false), Judgement::Broken);
  EXPECT_EQ(judge(Promise::None, false, true), Judgement::Unpromised);
  EXPECT_EQ(judge(Promise::None, true, true), Judgement::Kept);

  const Method misses = constant(false, Promise::Conservative);
  const Method alarms = constant(true, Promise::Conservative);
  EXPECT_EQ(verdict_words(misses, false, true, "f.vf:2"),
            "never-hit misses a hit at f.vf:2 (breaks CONSERVATIVE)");
  EXPECT_EQ(verdict_words(alarms, true, false, "f.vf:3"),
            "always-hit gives a false alarm at f.vf:3 (allowed: conservative)");
  EXPECT_EQ(verdict_words(constant(true, Promise::Exact), true, false),
            "always-hit gives a false alarm (breaks EXACT)");
  EXPECT_EQ(verdict_words(constant(false, Promise::None), false, true, "f.vf:1"),
            "never-hit answers no where exact says hit at f.vf:1 (no promise)");
  EXPECT_EQ(verdict_words(alarms, true, true, "f.vf:1"), "");
  EXPECT_EQ(describe(alarms, check(alarms, passing())),
            "always-hit says hit, the exact twin says no: gives a false alarm (allowed: "
            "conservative)");

  DisagreementTally t;
  t.add(Promise::Conservative, false, true);
  t.add(Promise::Conservative, true, false);
  t.add(Promise::Conservative, true, false);
  t.add(Promise::Conservative, true, true);
  DisagreementTally none;
  none.add(Promise::None, false, true);
  t.merge(none);
  EXPECT_EQ(t.misses, 2);
  EXPECT_EQ(t.false_alarms, 2);
  EXPECT_EQ(t.broken, 1);
  EXPECT_EQ(t.allowed, 2);
}

TEST(Checker, EveryPromisedMethodKeepsItOnTheHandMadeCases) {
  for (const Method& m : promised_methods())
    for (const Query& q : {crossing(), passing()}) EXPECT_TRUE(check(m, q).kept) << m.name;
}

TEST(Checker, CheckAllCountsAndKeepsTheFirstBroken) {
  const std::vector<Query> qs = {passing(), crossing(), crossing()};
  const std::vector<char> twin = {0, 1, 1};
  const CheckTally t = check_all(constant(false, Promise::Exact), qs, twin);
  EXPECT_EQ(t.checked, 3);
  EXPECT_EQ(t.broken, 2);
  EXPECT_EQ(t.first_broken, (std::vector<std::size_t>{1, 2}));
}

TEST(Checker, TwinAgainstAStoredTruth) {
  const Query q = crossing();
  EXPECT_FALSE(twin_matches_truth(std::nullopt, true).has_value());
  EXPECT_EQ(twin_matches_truth(false, twin_hit(q)), false);
  EXPECT_EQ(twin_matches_truth(true, twin_hit(q)), true);
}

TEST(Checker, BoxesOfTheRegistryContainTheExactFdh) {
  const Vec3 pts[3] = {{0.1, 0.2, 0.3}, {-1e10, 3, 0.7}, {1 / 3.0, 1e-300, -5}};
  for (const BoxMethod& m : all_box_methods()) EXPECT_EQ(check_box(m, pts, 3), -1) << m.k;
}

TEST(Checker, ABoxThatIsTooSmallIsCaught) {
  BoxMethod shrunk = all_box_methods().front();
  const auto build = shrunk.build;
  shrunk.build = [build](const Vec3* p, std::size_t n, double* lo, double* hi) {
    build(p, n, lo, hi);
    lo[0] = std::nextafter(lo[0], hi[0]);  // one ulp inside on the x slab
  };
  const Vec3 pts[2] = {{0.5, 0, 0}, {1, 1, 1}};
  EXPECT_EQ(check_box(shrunk, pts, 2), 0);
}

// A method whose directions do not fit its k cannot be checked: no direction is guessed.
TEST(Checker, ABoxMethodWithoutItsDirectionsIsRefused) {
  BoxMethod m = all_box_methods().front();
  m.directions.clear();
  const Vec3 pts[1] = {{0, 0, 0}};
  EXPECT_THROW(check_box(m, pts, 1), std::invalid_argument);
  EXPECT_THROW(check_overlap(m, {pts[0]}, {pts[0]}), std::invalid_argument);
}

TEST(Checker, OverlapOfTouchingBoxesIsKept) {
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 1, 1}}, b = {{1, 1, 1}, {2, 2, 2}};
  for (const BoxMethod& m : all_box_methods()) {
    const Verdicts v = check_overlap(m, a, b);
    EXPECT_TRUE(v.twin);
    EXPECT_TRUE(v.kept) << m.k;
  }
}

// A box method with its own integer direction (2, -3, 1), as a peer brings: the checker takes
// the exact extents along it. Two sets apart along it are disjoint exactly; a box that claims
// an overlap keeps a conservative promise, one that misses a slab's extent does not.
TEST(Checker, BoxesAlongAnyIntegerDirection) {
  BoxMethod m;
  m.k = 2;
  m.directions = {{2, -3, 1}};
  m.build = [](const Vec3* p, std::size_t n, double* lo, double* hi) {
    lo[0] = hi[0] = 2 * p[0].x - 3 * p[0].y + p[0].z;  // exact on small integers
    for (std::size_t i = 1; i < n; ++i) {
      const double v = 2 * p[i].x - 3 * p[i].y + p[i].z;
      lo[0] = std::min(lo[0], v), hi[0] = std::max(hi[0], v);
    }
  };
  m.overlap = [](const double*, const double*, const double*, const double*) { return true; };
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 0, 0}}, b = {{0, -1, 0}, {3, 0, 0}};
  EXPECT_EQ(check_box(m, a.data(), a.size()), -1);
  const Verdicts apart = check_overlap(m, a, b);  // a: [0, 2], b: [3, 6]
  EXPECT_FALSE(apart.twin);
  EXPECT_TRUE(apart.kept);
  const auto build = m.build;
  m.build = [build](const Vec3* p, std::size_t n, double* lo, double* hi) {
    build(p, n, lo, hi);
    hi[0] = std::nextafter(hi[0], 0.0);
  };
  EXPECT_EQ(check_box(m, b.data(), b.size()), 0);
}

TEST(Checker, CulledPairsAreTheExactPairsNotFound) {
  const std::vector<std::pair<int, int>> found = {{2, 0}, {0, 1}}, exact = {{0, 1}, {1, 1}, {2, 0}};
  EXPECT_EQ(culled_pairs(found, exact), (std::vector<std::pair<int, int>>{{1, 1}}));
}

// A method whose time of impact is the constant `said`, under `promise`.
Method timed(Toi said, TimePromise promise) {
  Method m;
  m.name = "timed";
  m.time_promise = promise;
  for (QueryToi& t : m.toi) t = [said](const Query&, double) { return said; };
  return m;
}

// crossing() meets the triangle at t* = 1/2 exactly.
TEST(Checker, TimePromisesAllowWhatTheySay) {
  const Query q = crossing();
  const TimeTwin twin = time_twin(q);
  ASSERT_TRUE(twin.hit);
  EXPECT_EQ(twin.t_star, 0.5);
  const double w = 0x1p-30;
  const auto check_with = [&](Toi said, TimePromise p) {
    return check_time(timed(said, p), q, w, twin);
  };
  // An enclosure of 1/2 within the width keeps both promises; 1/2 itself is neither early nor late.
  const TimeCheck exact_half = check_with({true, 0.5, 0.5}, TimePromise::Enclosure);
  EXPECT_TRUE(exact_half.kept);
  EXPECT_EQ(exact_half.early, 0);
  // Early but wide: never late, no enclosure.
  const TimeCheck wide = check_with({true, 0.25, 0.75}, TimePromise::Enclosure);
  EXPECT_TRUE(wide.too_wide);
  EXPECT_TRUE(wide.enclosed);
  EXPECT_FALSE(wide.kept);
  EXPECT_EQ(wide.early, 0.25);
  EXPECT_TRUE(check_with({true, 0.25, 0.75}, TimePromise::NeverLate).kept);
  // Late by one ulp: breaks both.
  const Toi late{true, std::nextafter(0.5, 1.0), std::nextafter(0.5, 1.0)};
  EXPECT_TRUE(check_with(late, TimePromise::NeverLate).late);
  EXPECT_FALSE(check_with(late, TimePromise::NeverLate).kept);
  EXPECT_FALSE(check_with(late, TimePromise::Enclosure).kept);
  EXPECT_TRUE(check_with(late, TimePromise::None).kept);
  // A missed contact is late; a zero TOI where t* > 0 is counted, and never late.
  const TimeCheck missed = check_with({}, TimePromise::NeverLate);
  EXPECT_TRUE(missed.late && missed.verdict_error && !missed.kept);
  const TimeCheck zero = check_with({true, 0, 1}, TimePromise::NeverLate);
  EXPECT_TRUE(zero.zero && zero.kept);
  EXPECT_EQ(zero.early, 0.5);
  EXPECT_EQ(describe(timed(late, TimePromise::NeverLate), check_with(late, TimePromise::NeverLate)),
            "timed's TOI is late: t_lo = 0.50000000000000011 > t* ~ 0.5");
  // A contact said where there is none: allowed by never-late alone.
  const Query p = passing();
  const TimeCheck alarm = check_time(timed({true, 0, 0}, TimePromise::NeverLate), p, w);
  EXPECT_TRUE(alarm.verdict_error && alarm.kept && !alarm.late);
  EXPECT_FALSE(check_time(timed({true, 0, 0}, TimePromise::Enclosure), p, w).kept);
  // Garbage breaks either promise.
  EXPECT_FALSE(check_with({true, 0.75, 0.25}, TimePromise::NeverLate).kept);
}

// A time's finding is judged by the time promise: late breaks it, earliness is allowed by
// never-late (in words that name how early, not the enclosure never-late says nothing of).
TEST(Checker, TimeFindingsAreJudgedByThePromise) {
  const Query q = crossing();
  const auto words = [&](Toi said, TimePromise p) {
    const Method m = timed(said, p);
    return judged_time_words(m, check_time(m, q, 0x1p-30));
  };
  const Toi late{true, 0.75, 0.75};
  EXPECT_EQ(words(late, TimePromise::NeverLate),
            "timed's TOI is late: t_lo = 0.75 > t* ~ 0.5 (breaks never-late)");
  EXPECT_EQ(words(late, TimePromise::Enclosure),
            "timed's TOI is late: t_lo = 0.75 > t* ~ 0.5 (breaks exact-enclosure)");
  EXPECT_EQ(words(late, TimePromise::None),
            "timed's TOI is late: t_lo = 0.75 > t* ~ 0.5 (no promise)");
  EXPECT_EQ(words({true, 0.25, 0.75}, TimePromise::NeverLate),
            "timed's TOI is early by 0.25 of the step, t* ~ 0.5 (allowed: never-late)");
  EXPECT_EQ(words({true, 0.5, 0.5}, TimePromise::Enclosure), "");
  const Method wide = timed({true, 0.25, 0.75}, TimePromise::Enclosure);
  EXPECT_EQ(judge(wide, check_time(wide, q, 0x1p-30)), Judgement::Broken);
}

TEST(Checker, TheTimeTallyCountsLateEarlyAndZero) {
  const Query q = crossing();
  TimeTally t;
  t.add(check_time(timed({true, 0.5, 0.5}, TimePromise::NeverLate), q, 1), 0);
  t.add(check_time(timed({true, 0, 0.5}, TimePromise::NeverLate), q, 1), 1);
  t.add(check_time(timed({true, 0.75, 0.75}, TimePromise::NeverLate), q, 1), 2);
  t.add(check_time(timed({true, 0.375, 0.5}, TimePromise::NeverLate), q, 1), 3);
  EXPECT_EQ(t.checked, 4);
  EXPECT_EQ(t.contacts, 4);
  EXPECT_EQ(t.late, 1);
  EXPECT_EQ(t.zero, 1);
  EXPECT_EQ(t.broken, 1);
  EXPECT_EQ(t.first_broken, (std::vector<std::size_t>{2}));
  EXPECT_EQ(t.early_max(), 0.5);
  EXPECT_EQ(t.early_median(), 0.125);  // of 0, 0.125, 0.5: the late one is not early
}

// The registry's robust keeps its enclosure, and the twin agrees with itself.
TEST(Checker, RobustAndTheTwinKeepTheirTimePromises) {
  Query moving = crossing();
  moving.x[5].z = moving.x[6].z = moving.x[7].z = 0.5;  // the triangle rises to meet it
  for (const Method& m : toi_methods()) {
    if (m.time_promise == TimePromise::None) continue;
    for (const Query& q : {crossing(), passing(), moving}) {
      const TimeCheck c = check_time(m, q, kDefaultToiWidth);
      EXPECT_TRUE(c.kept) << m.name << ": " << describe(m, c);
    }
  }
}

}  // namespace
}  // namespace fdh::verify
