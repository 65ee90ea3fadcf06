// The minimum-separation families (fdh/gen/families.hpp delta_families): every case asks at
// δ > 0, keeps its family's kind, shrinks keeping δ, and its truth is the exact δ twin's.
#include <gtest/gtest.h>

#include <cmath>

#include "fdh/check/registry.hpp"
#include "fdh/gen/case_kind.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/gen/simplify.hpp"

namespace fdh::verify {
namespace {

std::vector<std::string> delta_names() {
  std::vector<std::string> names;
  for (const Family& f : delta_families()) names.push_back(f.name);
  return names;
}

class DeltaFamily : public ::testing::TestWithParam<std::string> {};

TEST_P(DeltaFamily, AsksAtDeltaWithAKnownTruthAndItsKind) {
  const Family& f = *family_named(GetParam());
  int hits = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const Generated g = generate(f, seed);
    EXPECT_EQ(g.family, f.name);
    EXPECT_GT(g.query.min_distance, 0) << seed;
    EXPECT_TRUE(std::isfinite(g.query.min_distance)) << seed;
    ASSERT_NE(g.truth, Truth::Unknown) << seed;
    EXPECT_EQ(f.moving, case_kind_of(g.query) != CaseKind::Static) << seed;
    hits += g.truth == Truth::Yes;
  }
  EXPECT_GT(hits, 20);
  EXPECT_LT(hits, 200);
}

// The construction's minimum distance against the exact δ twin (reference/ exact::ccd_hit,
// which reads Query::min_distance): hit iff δ >= the exact minimum distance.
TEST_P(DeltaFamily, TheTruthIsTheExactTwins) {
  const Family& f = *family_named(GetParam());
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    const Generated g = generate(f, seed);
    EXPECT_EQ(twin_hit(g.query), g.truth == Truth::Yes)
        << f.name << " seed " << seed << " δ = " << g.query.min_distance;
  }
}

INSTANTIATE_TEST_SUITE_P(All, DeltaFamily, ::testing::ValuesIn(delta_names()),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

TEST(DeltaFamilies, AreNamedApartFromTheContactFamilies) {
  EXPECT_EQ(delta_families().size(), 8u);
  for (const Family& f : delta_families()) {
    EXPECT_EQ(f.name.rfind("delta-", 0), 0u) << f.name;
    for (const Family& c : all_families()) EXPECT_NE(c.name, f.name);
  }
  for (const Family& c : all_families()) EXPECT_EQ(generate(c, 7).query.min_distance, 0) << c.name;
}

// Shrinking keeps δ: every simplification keeps it, but a scale, which scales it with the points.
TEST(DeltaFamilies, SimplifyingKeepsOrScalesDelta) {
  const Generated g = generate(*family_named("delta-edge-edge"), 5);
  const double d = g.query.min_distance;
  for (const Query& s : simplifications(g.query)) {
    const double ratio = s.min_distance / d;
    int e = 0;
    EXPECT_EQ(std::frexp(ratio, &e), 0.5) << ratio;  // a power of two
    if (ratio != 1) {
      EXPECT_EQ(std::ldexp(g.query.x[1].x, e - 1), s.x[1].x);  // the points scaled alike
    }
  }
  const std::optional<Generated> shrunk = shrunk_failure(
      *family_named("delta-still"), 3, [](const Generated& h) { return h.query.min_distance > 0; });
  ASSERT_TRUE(shrunk);
  EXPECT_GT(shrunk->query.min_distance, 0);
}

}  // namespace
}  // namespace fdh::verify
