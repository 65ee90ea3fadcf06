// The suite's Kernel_checker property: on every generator family, static and moving, every
// method of the registry that makes a promise keeps it against the exact twin, through the one
// checker. A static query is asked twice: as a point-triangle query and as a CCD query whose
// triangle stays (so `robust` CCD is held to the static exact test too).
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "fdh/check/checker.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "test_name.hpp"

namespace fdh::verify {
namespace {

class Promises : public ::testing::TestWithParam<std::string> {};

std::vector<Decision> decisions_of(const Query& q) {
  if (decision_of(q) == Decision::PointTriangle)
    return {Decision::PointTriangle, Decision::VertexFaceCcd};
  return {decision_of(q)};
}

TEST_P(Promises, HoldOnEveryQueryOfTheFamily) {
  const Family& f = *family_named(GetParam());
  const std::vector<Method> promised = promised_methods();
  ASSERT_FALSE(promised.empty());
  EXPECT_TRUE(rc::check("promises/" + f.name, [&] {
    const Query q = (*gen_family(f)).query;
    for (const Decision d : decisions_of(q))
      for (const Method& m : promised) {
        const Verdicts v = check(m, q, d);
        if (!v.kept) RC_FAIL(describe(m, v) + " (" + to_string(d) + ")");
      }
  }));
}

INSTANTIATE_TEST_SUITE_P(All, Promises, ::testing::ValuesIn(every_family_name()),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace fdh::verify
