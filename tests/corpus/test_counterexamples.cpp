// The committed counterexamples: corpus/counterexamples/<method>/<family>.vf. Each must still
// show its method failing, while the exact twin still gives its stored truth and every method
// that promises the exact verdict keeps it (the checker).
#include <gtest/gtest.h>

#include <filesystem>

#include "fdh/check/checker.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
const fs::path kCounterexamples = FDH_SOURCE_DIR "/corpus/counterexamples";

TEST(Corpus, EveryCounterexampleStillFailsItsMethod) {
  const std::vector<Method> promised = promised_methods();
  int files = 0;
  for (const auto& dir : fs::directory_iterator(kCounterexamples)) {
    const Method m = select_methods({dir.path().filename().string()}).front();
    for (const auto& file : fs::directory_iterator(dir.path())) {
      SCOPED_TRACE(file.path().string());
      const std::vector<QueryRecord> qs = read_native(file.path().string());
      ASSERT_EQ(qs.size(), 1u);
      const Query& q = qs[0].query;
      ASSERT_TRUE(qs[0].has_truth());
      const bool twin = twin_hit(q);
      EXPECT_EQ(twin_matches_truth(stated(qs[0].truth), twin), true);
      for (const Method& p : promised) EXPECT_TRUE(check(p, q, twin).kept) << p.name;
      EXPECT_FALSE(check(m, q, twin).agree()) << m.name << " no longer fails here";
      // The family named by the file exists.
      EXPECT_NE(family_named(file.path().stem().string()), nullptr);
      ++files;
    }
  }
  EXPECT_GE(files, 30);
}

// Far from the origin linear-system also raises false alarms (docs/methods.md).
TEST(Corpus, LinearSystemRaisesAFalseAlarmFarFromTheOrigin) {
  const std::vector<QueryRecord> qs =
      read_native(FDH_SOURCE_DIR "/tests/data/linear_system_far_false_alarm.vf");
  ASSERT_EQ(qs.size(), 1u);
  const Method m = select_methods({"linear-system"}).front();
  const Verdicts v = check(m, qs[0].query);
  EXPECT_FALSE(v.twin);
  EXPECT_EQ(twin_matches_truth(stated(qs[0].truth), v.twin), true);
  EXPECT_TRUE(v.said);
}

// Scaled down, linear-system misses a face hit at the end of the step (docs/methods.md).
TEST(Corpus, LinearSystemMissesAFaceHitOnATinyQuery) {
  const std::vector<QueryRecord> qs =
      read_native(FDH_SOURCE_DIR "/tests/data/linear_system_tiny_face_miss.vf");
  ASSERT_EQ(qs.size(), 1u);
  const Verdicts v = check(select_methods({"linear-system"}).front(), qs[0].query);
  EXPECT_TRUE(v.twin);
  EXPECT_EQ(twin_matches_truth(stated(qs[0].truth), v.twin), true);
  EXPECT_FALSE(v.said);
}

}  // namespace
}  // namespace fdh::verify
