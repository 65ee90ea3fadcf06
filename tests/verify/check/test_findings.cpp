// A batch's findings (fdh/check/findings.hpp): the twin against a file's truth first, then each
// method against the twin in the checker's words and by its promise; the time twin's findings.
#include "fdh/check/findings.hpp"

#include <gtest/gtest.h>

namespace fdh::verify {
namespace {

// A vertical segment through the middle of the unit triangle in z = 0 (a hit, at t = 1/2), and
// the same segment beside it (no hit).
QueryRecord record(bool through, Truth truth, int line) {
  QueryRecord r;
  const double x = through ? 0.25 : 2;
  r.query.x = {Vec3{x, 0.25, 1},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
               Vec3{x, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  r.truth = truth, r.file = "f.vf", r.line = line, r.id = "q" + std::to_string(line);
  return r;
}

Method constant(const std::string& name, bool verdict, Promise promise) {
  Method m;
  m.name = name;
  m.promise = promise;
  for (QueryTest& t : m.test) t = [verdict](const Query&) { return verdict; };
  return m;
}

TEST(Findings, TwinAgainstTruthFirstThenEachMethodInTheCheckersWords) {
  // Line 1: a hit the file calls a hit; line 2: a hit the file calls no; line 3: no hit.
  const std::vector<QueryRecord> records = {record(true, Truth::Yes, 1), record(true, Truth::No, 2),
                                            record(false, Truth::Unknown, 3)};
  const std::vector<Method> methods = {constant("always", true, Promise::Conservative),
                                       constant("never", false, Promise::Exact),
                                       constant("loose", true, Promise::None)};
  const Classification c = classify(queries_of(records), truths_of(records), methods);
  const std::vector<Finding> found = findings(c, records, methods);
  ASSERT_EQ(found.size(), 5u);
  EXPECT_TRUE(found[0].truth);
  EXPECT_EQ(found[0].query, 1u);
  EXPECT_EQ(found[0].words, "exact disagrees with the file's truth at f.vf:2 (query q2)");
  EXPECT_EQ(found[1].method, "always");  // a false alarm on line 3, allowed
  EXPECT_EQ(found[1].judgement, Judgement::Allowed);
  EXPECT_EQ(found[1].words, verdict_words(methods[0], true, false, "f.vf:3 (query q3)"));
  EXPECT_EQ(found[2].method, "never");  // misses lines 1 and 2, broken
  EXPECT_EQ(found[2].judgement, Judgement::Broken);
  EXPECT_EQ(found[3].query, 1u);
  EXPECT_EQ(found[4].method, "loose");
  EXPECT_EQ(found[4].judgement, Judgement::Unpromised);
  EXPECT_EQ(findings(c, records, methods, Place::Line)[0].words,
            "exact disagrees with the file's truth at f.vf:2");
}

TEST(Findings, TimesLateOrEarlyOrBrokenAreFound) {
  const std::vector<QueryRecord> records = {record(true, Truth::Unknown, 1),
                                            record(false, Truth::Unknown, 2)};
  Method late;  // says 3/4 where t* = 1/2, never late promised: broken on line 1 only
  late.name = "late";
  late.time_promise = TimePromise::NeverLate;
  for (QueryToi& t : late.toi) t = [](const Query&, double) { return Toi{true, 0.75, 0.75}; };
  Method early = late;  // says 1/4: early by a quarter step, allowed by never-late
  early.name = "early";
  for (QueryToi& t : early.toi) t = [](const Query&, double) { return Toi{true, 0.25, 0.25}; };
  const std::vector<Method> methods = {late, early};
  const ToiClassification toi = classify_toi(queries_of(records), methods, 0x1p-30);
  const std::vector<TimeFinding> found = time_findings(toi, methods, 0.1);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].method, "late");
  EXPECT_TRUE(found[0].check.late);
  EXPECT_EQ(found[0].judgement, Judgement::Broken);
  EXPECT_EQ(found[1].method, "early");
  EXPECT_TRUE(found[1].early);
  EXPECT_EQ(found[1].judgement, Judgement::Allowed);
  EXPECT_TRUE(time_findings(toi, methods, 0.3).size() == 1u);  // a quarter step is tolerated
}

}  // namespace
}  // namespace fdh::verify
