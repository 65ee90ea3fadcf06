// Metamorphic properties: on every generator family, the methods that promise the exact verdict
// (robust and the exact twin) give the same verdict on a query and on each of its transforms
// (fdh/check/metamorphic.hpp). No oracle is needed; the transforms keep the truth.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "fdh/check/metamorphic.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "test_name.hpp"

namespace fdh::verify {
namespace {

class MetamorphicInvariance : public ::testing::TestWithParam<std::string> {};

TEST_P(MetamorphicInvariance, PromisedMethodsAreInvariantUnderEveryTransform) {
  const Family& f = *family_named(GetParam());
  std::vector<Method> promised;
  for (Method& m : all_methods())
    if (m.promise == Promise::Exact) promised.push_back(std::move(m));
  ASSERT_GE(promised.size(), 2u);  // the twin and robust
  EXPECT_TRUE(rc::check("metamorphic/" + f.name, [&] {
    const Query q = (*gen_family(f)).query;
    for (const Method& m : promised)
      if (const std::optional<MetamorphicFailure> broken = metamorphic_failure(m, q))
        RC_FAIL(describe(m, *broken));
  }));
}

INSTANTIATE_TEST_SUITE_P(All, MetamorphicInvariance, ::testing::ValuesIn(every_family_name()),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace fdh::verify
