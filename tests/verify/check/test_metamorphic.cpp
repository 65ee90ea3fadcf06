// The metamorphic transforms (fdh/check/metamorphic.hpp): each keeps the exact twin's verdict,
// none rounds a coordinate (it does not apply instead), and a method that changes its verdict
// under one is found.
#include "fdh/check/metamorphic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "fdh/gen/families.hpp"

namespace fdh::verify {
namespace {

const Transform& named(const std::string& name) {
  for (const Transform& t : all_transforms())
    if (t.name == name) return t;
  throw std::invalid_argument("no transform " + name);
}

TEST(Metamorphic, TransformsHaveDistinctNamesAndCoverTheIssue) {
  std::set<std::string> names;
  for (const Transform& t : all_transforms()) EXPECT_TRUE(names.insert(t.name).second) << t.name;
  for (const char* n : {"time-reversal", "axes-yzx", "translate", "velocity", "scale-up",
                        "scale-down", "corners-turn", "corners-flip", "edge-a-flip", "edges-swap"})
    EXPECT_EQ(names.count(n), 1u) << n;
}

TEST(Metamorphic, EveryTransformKeepsTheTwinsVerdictOnEveryFamily) {
  long checked = 0;
  for (const Family& f : all_families())
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const Query q = generate(f, seed).query;
      const bool truth = twin_hit(q);
      for (const Transform& t : all_transforms())
        if (const std::optional<Query> moved = t.apply(q)) {
          ++checked;
          EXPECT_EQ(twin_hit(*moved), truth) << f.name << " seed " << seed << " " << t.name;
        }
    }
  EXPECT_GT(checked, 1000);
}

Query vertex_face(double s) {
  Query q;
  q.x = {Vec3{s, s, s},  {0, 0, 0}, {s, 0, 0}, {0, s, 0},
         Vec3{s, s, -s}, {0, 0, 0}, {s, 0, 0}, {0, s, 0}};
  return q;
}

TEST(Metamorphic, ATransformThatWouldRoundDoesNotApply) {
  EXPECT_TRUE(named("translate").apply(vertex_face(1)));
  EXPECT_FALSE(named("translate").apply(vertex_face(std::ldexp(1.0, -60))));  // would round
  EXPECT_FALSE(named("velocity").apply(vertex_face(std::ldexp(1.0, -60))));
  EXPECT_FALSE(named("scale-up").apply(vertex_face(std::ldexp(1.0, 1010))));     // overflow
  EXPECT_FALSE(named("scale-down").apply(vertex_face(std::ldexp(1.0, -1060))));  // underflow
  EXPECT_TRUE(named("scale-down").apply(vertex_face(std::ldexp(1.0, -1000))));
}

TEST(Metamorphic, RelabellingAppliesToItsOwnKindOnly) {
  Query ee = vertex_face(1);
  ee.kind = QueryKind::EdgeEdge;
  EXPECT_TRUE(named("corners-turn").apply(vertex_face(1)));
  EXPECT_FALSE(named("corners-turn").apply(ee));
  EXPECT_TRUE(named("edges-swap").apply(ee));
  EXPECT_FALSE(named("edges-swap").apply(vertex_face(1)));
  const Query turned = *named("corners-turn").apply(vertex_face(1));
  EXPECT_EQ(turned.x[1], vertex_face(1).x[2]);
  EXPECT_EQ(turned.x[7], vertex_face(1).x[5]);
}

// Shrunk by `fdhcert fuzz --metamorphic --method linear-system --family parallel-land`: the
// point lands on a corner of the triangle, and linear-system's rounding sees it inside or out
// depending on which corner comes first.
Query corner_landing() {
  Query q;
  q.x = {Vec3{0.25, 0, -0.25}, {0, 0, 0}, {-1, 0.5, 0}, {0, 1, -0.5},
         Vec3{0, 0, 0},        {0, 0, 0}, {-1, 0.5, 0}, {0, 1, -0.5}};
  return q;
}

TEST(Metamorphic, FindsAMethodWhoseVerdictChanges) {
  const Method ls = select_methods({"linear-system"}).front();
  const std::optional<MetamorphicFailure> f = metamorphic_failure(ls, corner_landing());
  ASSERT_TRUE(f);
  EXPECT_NE(f->before, f->after);
  EXPECT_NE(describe(ls, *f).find("linear-system says "), std::string::npos);
  const MetamorphicCount n = count_metamorphic(ls, corner_landing());
  EXPECT_GT(n.violations, 0);
  EXPECT_GE(n.checked, n.violations);
  for (const Method& m : all_methods()) {
    if (m.promise != Promise::None) {
      EXPECT_FALSE(metamorphic_failure(m, corner_landing())) << m.name;
    }
  }
}

TEST(Metamorphic, AMethodIsNotCheckedWhereItMakesNoDecision) {
  const Method paper = select_methods({"paper-intended"}).front();
  Query moving = corner_landing();
  moving.x[5].z = 1;  // the triangle moves: paper-intended answers n/a
  EXPECT_EQ(count_metamorphic(paper, moving).checked, 0);
  // A static query whose transform (velocity) makes it moving: that transform is skipped.
  const MetamorphicCount n = count_metamorphic(paper, corner_landing());
  EXPECT_GT(n.checked, 0);
  EXPECT_LT(n.checked, long(all_transforms().size()));
}

}  // namespace
}  // namespace fdh::verify
