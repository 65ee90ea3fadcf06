// The exact reference agrees with what the construction of a query guarantees: its truth,
// contact kind and time. (That `robust` equals it is test_promises.cpp's.)
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "fdh/exact/point_triangle.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "test_name.hpp"

namespace fdh::verify {
namespace {

class PointTriangleFamily : public ::testing::TestWithParam<std::string> {};

TEST_P(PointTriangleFamily, ExactMatchesTheConstruction) {
  const Family& f = *family_named(GetParam());
  EXPECT_TRUE(rc::check("exact-matches-construction/" + f.name, [&f] {
    const Generated g = *gen_family(f);
    const Query& q = g.query;
    const exact::PointTriangleContact c =
        exact::point_triangle(q.b0(), q.b1(), q.d(), q.e(), q.f());
    if (const std::optional<bool> truth = stated(g.truth)) RC_ASSERT(c.hit == *truth);
    if (!g.kind.empty()) RC_ASSERT(std::string(exact::to_string(c.kind)) == g.kind);
    if (!g.time.empty()) RC_ASSERT(c.time == g.time);
    RC_ASSERT(c.hit == (c.kind != exact::ContactKind::None));
    // Two independent exact methods: the rational parametric one and CGAL's do_intersect.
    RC_ASSERT(c.hit == exact::point_triangle_hit(q.b0(), q.b1(), q.d(), q.e(), q.f()));
  }));
}

INSTANTIATE_TEST_SUITE_P(All, PointTriangleFamily, ::testing::ValuesIn(family_names(false)),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace fdh::verify
