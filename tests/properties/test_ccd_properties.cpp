// Moving queries (vertex-face with a moving triangle, edge-edge): `exact` agrees with what a
// construction guarantees (truth, earliest time); and
// exact's contact time really is the first contact: the query touches inside the reported
// interval and not before it. On static queries, the CCD and the static exact test (CGAL's
// do_intersect) are two independent exact methods, and they must agree.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>

#include "fdh/exact/ccd.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "test_name.hpp"

namespace fdh::verify {
namespace {

class MovingFamilyTest : public ::testing::TestWithParam<std::string> {};

TEST_P(MovingFamilyTest, ExactMatchesTheConstruction) {
  const Family& f = *family_named(GetParam());
  EXPECT_TRUE(rc::check("ccd-exact-matches-construction/" + f.name, [&f] {
    const Generated g = *gen_family(f);
    const exact::CcdContact c = exact::ccd(g.query);
    if (const std::optional<bool> truth = stated(g.truth)) RC_ASSERT(c.hit == *truth);
    if (!g.time.empty()) {
      RC_ASSERT(c.time_exact());
      RC_ASSERT(c.time_lo == g.time);
    }
  }));
}

TEST_P(MovingFamilyTest, ContactTimeIsTheFirstContact) {
  const Family& f = *family_named(GetParam());
  EXPECT_TRUE(rc::check("ccd-time-is-first-contact/" + f.name, [&f] {
    const Query q = (*gen_family(f)).query;
    exact::CcdOptions o;
    o.time_bits = 40;
    const exact::CcdContact c = exact::ccd(q, o);
    if (!c.hit) return;  // most random motions miss
    const double lo = c.time_lo_down, hi = c.time_hi_up;
    RC_ASSERT(0 <= lo && lo <= hi && hi <= 1);
    if (!c.time_exact()) RC_ASSERT(hi - lo < 0x1p-39);
    RC_ASSERT(exact::ccd(q, {lo, hi, 0}).hit);  // it touches in there
    if (lo > 0)                                 // and never before
      RC_ASSERT(!exact::ccd(q, {0, std::nextafter(lo, -1.0), 0}).hit);
  }));
}

INSTANTIATE_TEST_SUITE_P(All, MovingFamilyTest, ::testing::ValuesIn(family_names(true)),
                         [](const auto& info) { return test_name(info.param); });

class StaticFamilyCcd : public ::testing::TestWithParam<std::string> {};

TEST_P(StaticFamilyCcd, CcdEqualsStaticExact) {
  const Family& f = *family_named(GetParam());
  EXPECT_TRUE(rc::check("ccd-on-static/" + f.name, [&f] {
    const Query q = (*gen_family(f)).query;
    const bool e = exact::point_triangle_hit(q.b0(), q.b1(), q.d(), q.e(), q.f());
    RC_ASSERT(exact::ccd_hit(q) == e);
  }));
}

INSTANTIATE_TEST_SUITE_P(All, StaticFamilyCcd, ::testing::ValuesIn(family_names(false)),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace fdh::verify
