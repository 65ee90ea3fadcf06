// δ in the registry and the metamorphic transforms (issue 30): the paper's readings and
// linear-system are n/a at δ > 0, the twin, robust and float-cubic answer; the transforms keep δ
// (the scales scale it) and the exact δ verdict.
#include <gtest/gtest.h>

#include <cmath>

#include "fdh/check/metamorphic.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/gen/families.hpp"

namespace fdh::verify {
namespace {

// A point 1 above a still triangle's face, passing beside it: contact no, within δ = 1 yes.
Query above_face(double delta) {
  Query q;
  q.x = {Vec3{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
         Vec3{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  q.min_distance = delta;
  return q;
}

TEST(MinDistanceRegistry, ThePaperMethodsAreNotApplicableAtDelta) {
  const Query contact = above_face(0), within = above_face(1);
  for (const Method& m : all_methods()) {
    const bool answers = m.name == "exact" || m.name == "robust" || m.name == "float-cubic";
    EXPECT_EQ(m.answers_min_distance, answers) << m.name;
    EXPECT_TRUE(m.applies_to(contact)) << m.name;
    EXPECT_EQ(m.applies_to(within), answers) << m.name;
  }
}

// The static δ question goes through the CCD entry points: a still point at distance 1 of the
// face is within δ = 1 and not within δ = 1 - 2^-53.
TEST(MinDistanceRegistry, TheStaticTwinAndRobustAnswerTheDeltaQuestion) {
  const std::vector<Method> ms = select_methods({"exact", "robust"});
  for (const Method& m : ms) {
    EXPECT_FALSE(m.hit(above_face(0))) << m.name;
    EXPECT_TRUE(m.hit(above_face(1))) << m.name;
    EXPECT_FALSE(m.hit(above_face(std::nextafter(1.0, 0.0)))) << m.name;
  }
  EXPECT_TRUE(twin_hit(above_face(1)));
  EXPECT_FALSE(twin_hit(above_face(0.5)));
}

TEST(MinDistanceTransforms, ScalesScaleDeltaAndTheOthersKeepIt) {
  const Query q = above_face(0.75);
  int scaled = 0;
  for (const Transformed& t : transforms_of(q)) {
    const std::string& name = t.transform->name;
    if (name.rfind("scale", 0) == 0) {
      ++scaled;
      EXPECT_EQ(t.query.min_distance / q.min_distance, t.query.x[2].x / q.x[2].x) << name;
    } else {
      EXPECT_EQ(t.query.min_distance, q.min_distance) << name;
    }
  }
  EXPECT_GE(scaled, 6);
  // A δ that would leave the normal range is not scaled: the transform does not apply.
  Query tiny = q;
  tiny.min_distance = 0x1p-1000;
  for (const Transformed& t : transforms_of(tiny))
    EXPECT_NE(t.transform->name, "scale-2^-60") << "δ would be subnormal";
}

// Every transform keeps the exact δ verdict: robust (exact) changes none, on every delta family.
TEST(MinDistanceTransforms, KeepTheExactDeltaVerdict) {
  const Method robust = select_methods({"robust"}).front();
  for (const Family& f : delta_families())
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
      const Query q = generate(f, seed).query;
      const bool twin = twin_hit(q);
      for (const Transformed& t : transforms_of(q)) {
        EXPECT_EQ(twin_hit(t.query), twin) << f.name << " " << seed << " " << t.transform->name;
        EXPECT_EQ(robust.hit(t.query), twin) << f.name << " " << seed << " " << t.transform->name;
      }
    }
}

}  // namespace
}  // namespace fdh::verify
