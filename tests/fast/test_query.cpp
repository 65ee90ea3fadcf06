// fdh::Query is plain data: 8 points, a kind and the minimum separation, no strings (issue 21),
// with named vertices that read the points in the documented order.
#include "fdh/query.hpp"

#include <gtest/gtest.h>

#include <type_traits>

namespace fdh {
namespace {

// No string, no provenance: a query is copied as plain memory.
static_assert(std::is_trivially_copyable_v<Query>);
static_assert(sizeof(Query) <=
              sizeof(QueryKind) + 8 * sizeof(Vec3) + sizeof(double) + alignof(Vec3));

Query numbered() {
  Query q;
  for (int i = 0; i < 8; ++i) q.x[i] = Vec3{double(i), 0, 0};
  return q;
}

TEST(Query, VertexFaceNamesFollowThePointOrder) {
  const Query q = numbered();
  const Vec3* names[8] = {&q.v_t0(), &q.f0_t0(), &q.f1_t0(), &q.f2_t0(),
                          &q.v_t1(), &q.f0_t1(), &q.f1_t1(), &q.f2_t1()};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(names[i], &q.x[i]) << i;
}

TEST(Query, EdgeEdgeNamesFollowThePointOrder) {
  const Query q = numbered();
  const Vec3* names[8] = {&q.ea0_t0(), &q.ea1_t0(), &q.eb0_t0(), &q.eb1_t0(),
                          &q.ea0_t1(), &q.ea1_t1(), &q.eb0_t1(), &q.eb1_t1()};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(names[i], &q.x[i]) << i;
}

TEST(Query, ThePapersNamesAreTheStaticVertexFaceOnes) {
  Query q = numbered();
  EXPECT_FALSE(q.is_static_vf());
  q.x[5] = q.x[1], q.x[6] = q.x[2], q.x[7] = q.x[3];
  EXPECT_TRUE(q.is_static_vf());
  EXPECT_EQ(&q.b0(), &q.v_t0());
  EXPECT_EQ(&q.b1(), &q.v_t1());
  EXPECT_EQ(&q.d(), &q.f0_t0());
  EXPECT_EQ(&q.e(), &q.f1_t0());
  EXPECT_EQ(&q.f(), &q.f2_t0());
  q.kind = QueryKind::EdgeEdge;
  EXPECT_FALSE(q.is_static_vf());
}

}  // namespace
}  // namespace fdh
