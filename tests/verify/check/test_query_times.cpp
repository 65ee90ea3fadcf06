// Per-query times (fdh/check/query_times.hpp): the ratios' maximum, median, worst query and count
// above the limit per decision, from given times; and timing fills every applicable query.
#include "fdh/check/query_times.hpp"

#include <gtest/gtest.h>

namespace fdh::verify {
namespace {

Query moving_vf(double dz) {
  Query q;
  q.kind = QueryKind::VertexFace;
  q.x = {Vec3{0.2, 0.2, 1},  {0, 0, 0},  {1, 0, 0},  {0, 1, 0},
         Vec3{0.2, 0.2, -1}, {0, 0, dz}, {1, 0, dz}, {0, 1, dz}};
  return q;
}

Query static_vf() {
  return moving_vf(0);  // the triangle stays
}

TEST(QueryTimes, RatiosPerDecision) {
  const std::vector<Query> qs = {moving_vf(0.5), moving_vf(0.25), moving_vf(0.125), static_vf()};
  const std::vector<Method> methods = select_methods({"robust", "exact"});
  // times[m][i]: robust over exact is 1.5, 0.5, 1.0 on the moving queries, 2 on the static one.
  const std::vector<std::vector<double>> times = {{3, 1, 4, 2}, {2, 2, 4, 1}};
  const std::vector<TimeRatio> r = time_ratios(qs, times, methods, 1, 1.1);
  ASSERT_EQ(r.size(), 4u);  // robust and exact, each for point-triangle and vertex-face-ccd
  EXPECT_EQ(r[0].method, "robust");
  EXPECT_EQ(r[0].decision, Decision::PointTriangle);
  EXPECT_EQ(r[0].queries, 1u);
  EXPECT_DOUBLE_EQ(r[0].max, 2);
  EXPECT_EQ(r[0].worst, 3u);
  EXPECT_EQ(r[1].decision, Decision::VertexFaceCcd);
  EXPECT_EQ(r[1].queries, 3u);
  EXPECT_DOUBLE_EQ(r[1].max, 1.5);
  EXPECT_DOUBLE_EQ(r[1].median, 1.0);
  EXPECT_EQ(r[1].worst, 0u);
  EXPECT_EQ(r[1].over, 1u);
  EXPECT_DOUBLE_EQ(r[3].max, 1.0);  // exact over itself
}

TEST(QueryTimes, EveryApplicableQueryGetsATime) {
  const std::vector<Query> qs = {moving_vf(0.5), static_vf()};
  const std::vector<Method> methods = select_methods({"robust", "paper-intended"});
  const auto t = time_each_query(qs, methods, 1);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_GT(t[0][0], 0);
  EXPECT_GT(t[0][1], 0);
  EXPECT_EQ(t[1][0], 0);  // paper-intended does not apply to a moving query
  EXPECT_GT(t[1][1], 0);
}

}  // namespace
}  // namespace fdh::verify
