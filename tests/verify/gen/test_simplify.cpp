// Shrinking's second pass (fdh/gen/simplify.hpp): it keeps the failure, stops motion, moves the
// case toward the origin and shortens coordinates, and never makes a query less simple.
#include "fdh/gen/simplify.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fdh/gen/case_kind.hpp"
#include "fdh/gen/families.hpp"

namespace fdh::verify {
namespace {

TEST(Simplify, BinaryLengthCountsTheDigitsWrittenInBinary) {
  EXPECT_EQ(binary_length(0), 0);
  EXPECT_EQ(binary_length(1), 1);
  EXPECT_EQ(binary_length(-3), 2);
  EXPECT_EQ(binary_length(8), 4);
  EXPECT_EQ(binary_length(0.75), 2);
  EXPECT_EQ(binary_length(5.5), 4);
  EXPECT_EQ(binary_length(std::ldexp(1.0, -40)), 40);
  EXPECT_EQ(binary_length(std::ldexp(1.0, 60) + std::ldexp(1.0, 8)), 61);
}

Query moving_query() {
  Query q;
  q.kind = QueryKind::VertexFace;
  q.x = {Vec3{5.75, -3.125, 1e9}, {7, 1.5, 0.1}, {-2, 3, 4}, {1, 1, 1},
         Vec3{6.25, 0.5, 1e9},    {7, 2.5, 0.1}, {-2, 3, 5}, {1, 0, 1}};
  return q;
}

TEST(Simplify, KeepsTheFailureAndDropsEverythingElse) {
  // Fails while the point starts at x >= 3: all else is noise.
  const auto fails = [](const Query& q) { return q.x[0].x >= 3; };
  const Query s = simplify_failure(moving_query(), fails);
  EXPECT_TRUE(fails(s));
  EXPECT_EQ(s.kind, QueryKind::VertexFace);
  EXPECT_TRUE(s.x[0].x == 3 || s.x[0].x == 4) << s.x[0].x;
  for (int i = 0; i < 8; ++i)
    for (int a = 0; a < 3; ++a)
      if (!(a == 0 && (i == 0 || i == 4))) {
        EXPECT_EQ(s.x[i][a], 0) << i << " " << a;
      }
  EXPECT_EQ(simplicity_of(s).moving, 0);  // x[4].x followed x[0].x: the point stopped
  EXPECT_LT(simplicity_of(s), simplicity_of(moving_query()));
}

TEST(Simplify, KeepsTheMotionAFailureNeeds) {
  // Fails while the triangle's corner a moves by exactly 1 along y.
  const auto fails = [](const Query& q) { return q.x[5].y - q.x[1].y == 1; };
  const Query s = simplify_failure(moving_query(), fails);
  EXPECT_TRUE(fails(s));
  EXPECT_EQ(simplicity_of(s).moving, 1);
  EXPECT_LT(simplicity_of(s), simplicity_of(moving_query()));
}

TEST(Simplify, EveryCandidateIsExactAndKeepsTheKind) {
  Query q = moving_query();
  q.kind = QueryKind::EdgeEdge;
  for (const Query& c : simplifications(q)) {
    EXPECT_EQ(c.kind, QueryKind::EdgeEdge);
    for (const Vec3& p : c.x) EXPECT_TRUE(std::isfinite(max_abs(p)));
  }
}

// A family's case shrunk through both passes still fails; a changed query drops the truth the
// construction gave it.
TEST(Simplify, ShrunkFailureOfAMovingFamily) {
  const Family& f = *family_named("parallel-edges");
  // Fails wherever edge A's start lies off the x axis.
  const auto fails = [](const Generated& g) { return g.query.x[0].y != 0 || g.query.x[0].z != 0; };
  int shrunk = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const std::optional<Generated> g = shrunk_failure(f, seed, fails);
    if (!g) continue;
    ++shrunk;
    EXPECT_TRUE(fails(*g));
    EXPECT_EQ(g->query.kind, QueryKind::EdgeEdge);
    EXPECT_EQ(simplicity_of(g->query).moving, 0);
    // x[0] = x[4] off the axis by one short coordinate; the edges, drawn whole, stay whole
    // (case_kind.hpp) in a few more short coordinates: 12 binary digits in all on these seeds.
    EXPECT_EQ(collapsed_primitives(g->query), 0u);
    EXPECT_LE(simplicity_of(g->query).length, 12) << simplicity_of(g->query).length;
    EXPECT_EQ(g->truth, Truth::Unknown);
  }
  EXPECT_GT(shrunk, 0);
}

// A shrink step that leaves the kind of the case drawn is refused: with a predicate that every
// query meets, a moving vertex-face family's case stays a moving triangle (not the all-zero
// static query), a static family's stays static, an edge-edge family's stays edge-edge, and no
// triangle or edge drawn whole collapses to coincident points.
TEST(Simplify, ShrunkFailureKeepsTheKindOfTheCaseDrawn) {
  const auto always = [](const Generated&) { return true; };
  for (const char* name : {"hourglass", "generic-moving", "angled", "parallel-edges"}) {
    SCOPED_TRACE(name);
    const Family& f = *family_named(name);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const CaseKind drawn = case_kind_of(generate(f, seed).query);
      const std::optional<Generated> g = shrunk_failure(f, seed, always);
      ASSERT_TRUE(g);
      EXPECT_EQ(to_string(case_kind_of(g->query)), to_string(drawn));
      EXPECT_TRUE(keeps_kind(generate(f, seed).query, g->query));
    }
  }
  EXPECT_EQ(case_kind_of(generate(*family_named("hourglass"), 1).query),
            CaseKind::MovingVertexFace);
  EXPECT_EQ(case_kind_of(generate(*family_named("angled"), 1).query), CaseKind::Static);
}

TEST(Simplify, CollapsedPrimitivesAreCoincidentPoints) {
  Query q;  // all zero: every primitive collapsed
  EXPECT_EQ(collapsed_primitives(q), 3u);
  q.kind = QueryKind::EdgeEdge;
  EXPECT_EQ(collapsed_primitives(q), 15u);
  q.x[1] = {1, 0, 0};  // edge a whole at t = 0
  EXPECT_EQ(collapsed_primitives(q), 14u);
  Query drawn = q;
  drawn.x[5] = {0, 1, 0};  // and at t = 1
  EXPECT_TRUE(keeps_kind(drawn, drawn));
  EXPECT_FALSE(keeps_kind(drawn, q));  // collapses edge a at t = 1
  EXPECT_TRUE(keeps_kind(q, drawn));
}

}  // namespace
}  // namespace fdh::verify
