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
  EXPECT_EQ(describe(liar, v), "never-hit says no, the exact twin says hit");
  EXPECT_TRUE(check(constant(true, Promise::Conservative), passing()).kept);
  EXPECT_FALSE(check(constant(false, Promise::Conservative), crossing()).kept);
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

}  // namespace
}  // namespace fdh::verify
