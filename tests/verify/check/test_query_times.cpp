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

// The spread of each method's times: lower median, nearest-rank 90th percentile and maximum
// over the queries it applies to (0 where it does not).
TEST(QueryTimes, SpreadsPerMethod) {
  const std::vector<Method> methods = select_methods({"robust", "paper-intended"});
  std::vector<double> robust;
  for (int i = 1; i <= 20; ++i) robust.push_back(double(21 - i));  // 20, 19, ..., 1
  const std::vector<std::vector<double>> times = {robust, std::vector<double>(20, 0)};
  const std::vector<TimeSpread> s = time_spreads(times, methods);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].method, "robust");
  EXPECT_EQ(s[0].queries, 20u);
  EXPECT_DOUBLE_EQ(s[0].median, 10);  // the 10th of 20
  EXPECT_DOUBLE_EQ(s[0].p90, 18);     // the 18th of 20
  EXPECT_DOUBLE_EQ(s[0].max, 20);
  EXPECT_EQ(s[0].slowest, 0u);
  EXPECT_EQ(s[1].queries, 0u);
  EXPECT_EQ(s[1].max, 0);
  // One query: all three are its time.
  const std::vector<TimeSpread> one = time_spreads({{0, 7}}, {methods[0]});
  EXPECT_EQ(one[0].queries, 1u);
  EXPECT_DOUBLE_EQ(one[0].median, 7);
  EXPECT_DOUBLE_EQ(one[0].p90, 7);
  EXPECT_EQ(one[0].slowest, 1u);
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
