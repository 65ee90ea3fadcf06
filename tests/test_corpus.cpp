// The committed counterexamples: corpus/counterexamples/<method>/<family>.vf. Each must still
// show its method failing, while exact still gives its stored truth and robust agrees.
#include <gtest/gtest.h>

#include <filesystem>

#include "fdh/gen/static_families.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
const fs::path kCorpus = FDH_SOURCE_DIR "/corpus/counterexamples";

TEST(Corpus, EveryCounterexampleStillFailsItsMethod) {
  const Method exact = select_methods({"exact"}).front(),
               robust = select_methods({"robust"}).front();
  int files = 0;
  for (const auto& dir : fs::directory_iterator(kCorpus)) {
    const Method m = select_methods({dir.path().filename().string()}).front();
    for (const auto& file : fs::directory_iterator(dir.path())) {
      SCOPED_TRACE(file.path().string());
      const std::vector<Query> qs = read_native(file.path().string());
      ASSERT_EQ(qs.size(), 1u);
      const Query& q = qs[0];
      ASSERT_TRUE(q.has_truth());
      EXPECT_EQ(exact.hit(q), bool(q.truth));
      EXPECT_EQ(robust.hit(q), bool(q.truth));
      EXPECT_NE(m.hit(q), bool(q.truth)) << m.name << " no longer fails here";
      // The family named by the file exists.
      EXPECT_TRUE(family_by_name(file.path().stem().string()).has_value());
      ++files;
    }
  }
  EXPECT_GE(files, 30);
}

}  // namespace
}  // namespace fdh::verify
