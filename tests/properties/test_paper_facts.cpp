// Property 5: true facts about the paper's two readings and the linear system, one per family,
// each checked against `exact` on every generated query. Where a method fails instead, a
// minimal counterexample is kept in corpus/counterexamples/<method>/<family>.vf
// (test_corpus.cpp); docs/methods.md explains both.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "fdh/exact/point_triangle.hpp"
#include "fdh/gen/static_families.hpp"
#include "fdh/check/registry.hpp"
#include "test_name.hpp"

namespace fdh::verify {
namespace {

enum class Fact {
  AlwaysNo,         // answers "no" on every query of the family
  AlwaysYes,        // answers "hit" on every query of the family
  NeverMisses,      // no false negative
  NoFalseAlarm,     // no false positive
  NeverMissesFace,  // no false negative where exact's contact is through the face's interior
};

struct Claim {
  const char* method;
  Family family;
  Fact fact;
  const char* why;
};

const Claim kClaims[] = {
    // paper-literal: for N1 != 0 it needs B' == N exactly, so it misses crossings; for N1 == 0
    // it tests N2 = BB'·B'D, which is <= 0 whenever B starts on the plane or does not move.
    {"paper-literal", Family::ParallelCross, Fact::AlwaysNo, "B' never lands on N"},
    {"paper-literal", Family::ThroughEdge, Fact::AlwaysNo, "B' never lands on N"},
    {"paper-literal", Family::ThroughVertex, Fact::AlwaysNo, "B' never lands on N"},
    {"paper-literal", Family::Grazing, Fact::AlwaysNo, "B' never lands on N"},
    {"paper-literal", Family::ParallelShort, Fact::AlwaysNo, "correct: no contact"},
    {"paper-literal", Family::ParallelLand, Fact::AlwaysYes, "B' == N: N3 = 0, inside or not"},
    {"paper-literal", Family::ParallelStart, Fact::AlwaysYes, "N1 = 0, N2 = -|BB'|^2"},
    {"paper-literal", Family::ZeroMotion, Fact::AlwaysYes, "N1 = 0, N2 = 0"},
    {"paper-literal", Family::Degenerate, Fact::AlwaysNo, "N is NaN"},
    // paper-intended: a plane-crossing test with no inside test. It never misses, but for
    // slivers, whose rounded normal can point the wrong way, and zero-area triangles (NaN).
    {"paper-intended", Family::ParallelCross, Fact::AlwaysYes, "crosses the plane"},
    {"paper-intended", Family::ParallelLand, Fact::AlwaysYes, "reaches the plane"},
    {"paper-intended", Family::ParallelStart, Fact::AlwaysYes, "starts on the plane"},
    {"paper-intended", Family::ParallelShort, Fact::AlwaysNo, "correct: no contact"},
    {"paper-intended", Family::ThroughEdge, Fact::AlwaysYes, "correct: hit"},
    {"paper-intended", Family::ThroughVertex, Fact::AlwaysYes, "correct: hit"},
    {"paper-intended", Family::HairOutsideEdge, Fact::AlwaysYes, "no inside test"},
    {"paper-intended", Family::InPlane, Fact::AlwaysYes, "parallel branch: N2 = -|BB'|^2"},
    {"paper-intended", Family::ZeroMotion, Fact::AlwaysYes, "parallel branch: N2 = 0"},
    {"paper-intended", Family::Angled, Fact::NeverMisses, "sign of the heights"},
    {"paper-intended", Family::Grazing, Fact::NeverMisses, "sign of the heights"},
    {"paper-intended", Family::FarFromOrigin, Fact::NeverMisses, "sign of the heights"},
    {"paper-intended", Family::Tiny, Fact::NeverMisses, "sign of the heights"},
    {"paper-intended", Family::Degenerate, Fact::AlwaysNo, "N is NaN"},
    // linear-system: never a false alarm but on slivers; misses what touches the boundary
    // (rounded u, v, t), everything singular (in-plane, no motion, zero area), and face hits
    // only where rounding is large (far from the origin, slivers).
    {"linear-system", Family::ParallelCross, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::ParallelLand, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::ParallelStart, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::Angled, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::ThroughEdge, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::ThroughVertex, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::Grazing, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::FarFromOrigin, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::Tiny, Fact::NoFalseAlarm, ""},
    {"linear-system", Family::ParallelShort, Fact::AlwaysNo, "correct: no contact"},
    {"linear-system", Family::HairOutsideEdge, Fact::AlwaysNo, "correct: no contact"},
    {"linear-system", Family::InPlane, Fact::AlwaysNo, "singular"},
    {"linear-system", Family::ZeroMotion, Fact::AlwaysNo, "singular"},
    {"linear-system", Family::Degenerate, Fact::AlwaysNo, "singular"},
    {"linear-system", Family::ParallelCross, Fact::NeverMissesFace, ""},
    {"linear-system", Family::Angled, Fact::NeverMissesFace, ""},
    {"linear-system", Family::Grazing, Fact::NeverMissesFace, ""},
    {"linear-system", Family::Tiny, Fact::NeverMissesFace, ""},
};

class PaperFacts : public ::testing::TestWithParam<Claim> {};

TEST_P(PaperFacts, Hold) {
  const Claim c = GetParam();
  const Method m = select_methods({c.method}).front();
  const std::string name = std::string("fact/") + c.method + "/" + family_name(c.family);
  EXPECT_TRUE(rc::check(name, [&] {
    const Query q = (*gen_family(c.family)).query;
    const bool v = m.hit(q);
    const exact::PointTriangleContact e =
        exact::point_triangle(q.b0(), q.b1(), q.d(), q.e(), q.f());
    switch (c.fact) {
      case Fact::AlwaysNo:
        RC_ASSERT(!v);
        break;
      case Fact::AlwaysYes:
        RC_ASSERT(v);
        break;
      case Fact::NeverMisses:
        RC_ASSERT(v || !e.hit);
        break;
      case Fact::NoFalseAlarm:
        RC_ASSERT(!v || e.hit);
        break;
      case Fact::NeverMissesFace:
        RC_ASSERT(v || e.kind != exact::ContactKind::Face);
        break;
    }
  })) << c.why;
}

std::string claim_name(const ::testing::TestParamInfo<Claim>& info) {
  static const char* const kFacts[] = {"always_no", "always_yes", "never_misses", "no_false_alarm",
                                       "never_misses_face"};
  return test_name(std::string(info.param.method) + "_" + family_name(info.param.family) + "_" +
                   kFacts[int(info.param.fact)]);
}

INSTANTIATE_TEST_SUITE_P(All, PaperFacts, ::testing::ValuesIn(kClaims), claim_name);

}  // namespace
}  // namespace fdh::verify
