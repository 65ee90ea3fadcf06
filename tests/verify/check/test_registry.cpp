// The registry (fdh/check/registry.hpp): one exact twin, unique names, what each method decides.
#include "fdh/check/registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace fdh::verify {
namespace {

TEST(Registry, NamesAreUniqueAndExactlyOneEntryIsTheTwin) {
  std::set<std::string> names;
  int twins = 0;
  for (const Method& m : all_methods()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    twins += m.is_twin;
    if (m.is_twin) {
      EXPECT_EQ(m.promise, Promise::Exact);
    }
  }
  EXPECT_EQ(twins, 1);
}

TEST(Registry, TheTwinMakesEveryQueryDecision) {
  for (const Method& m : all_methods())
    if (m.is_twin) {
      for (const Decision d : kQueryDecisions) EXPECT_TRUE(m.test[std::size_t(d)]) << to_string(d);
    }
}

TEST(Registry, PromisedMethodsLeaveOutTheTwinAndTheMeasuredOnes) {
  for (const Method& m : promised_methods()) {
    EXPECT_FALSE(m.is_twin);
    EXPECT_NE(m.promise, Promise::None);
  }
  EXPECT_FALSE(promised_methods().empty());
}

TEST(Registry, UnknownNamesListTheKnownOnes) {
  try {
    select_methods({"nonsense"});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown method 'nonsense' (known: "), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("--plugin FILE"), std::string::npos);  // the hint
  }
  EXPECT_THROW(narrow_phase_named("float-cubic"), std::invalid_argument);  // no static test
  EXPECT_THROW(all_methods(7), std::invalid_argument);
}

TEST(Registry, NarrowPhasesAreThePlainStaticTests) {
  for (const std::string& n : narrow_phase_names()) EXPECT_NE(narrow_phase_named(n), nullptr);
}

TEST(Registry, BoxMethodsCoverTheCertifiedK) {
  std::set<int> ks;
  for (const BoxMethod& m : all_box_methods()) ks.insert(m.k);
  EXPECT_EQ(ks, std::set<int>(kCertifiedK.begin(), kCertifiedK.end()));
}

// The project's box methods carry fdh::Kdop<k>'s slab directions, in their order: nothing falls
// back to them when a method has none.
TEST(Registry, BoxMethodsCarryTheirSlabDirections) {
  for (const BoxMethod& m : all_box_methods()) {
    ASSERT_EQ(m.directions.size() * 2, std::size_t(m.k));
    for (int s = 0; s < m.k / 2; ++s) {
      const Direction d = slab_direction(m.k, s);
      EXPECT_TRUE(m.directions[s].x == d.x && m.directions[s].y == d.y && m.directions[s].z == d.z)
          << m.k << " " << s;
    }
  }
  EXPECT_EQ(kdop_directions(26).size(), 13u);
}

}  // namespace
}  // namespace fdh::verify
