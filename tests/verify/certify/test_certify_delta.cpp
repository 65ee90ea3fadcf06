// certify's minimum-separation stage (issue 30): its δ promise lines and δ metamorphic counts,
// in the certificate and its files; 0 skips it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fdh/certify/certify.hpp"
#include "fdh/gen/families.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

CertifyOptions tiny(const fs::path& out) {
  const fs::path corpus = out / "corpus";
  fs::create_directories(corpus);
  fs::copy_file(FDH_SOURCE_DIR "/tests/data/moving.vf", corpus / "moving.vf");
  CertifyOptions o;
  o.corpus_dir = corpus.string();
  o.out_dir = (out / "certificate").string();
  o.per_family = 16;
  o.soups = 1;
  o.peer_cases = 10;
  return o;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(CertifyDelta, JudgesTheMethodsThatAnswerDeltaAndCountsTheTransforms) {
  const fs::path out = fresh_temp_dir("certify_delta");
  const Certificate c = certify(tiny(out));
  write_certificate(c);
  const DeltaStage& d = c.delta;
  ASSERT_TRUE(d.run);
  EXPECT_EQ(d.families.size(), delta_families().size());
  EXPECT_EQ(d.family_queries, 4 * long(delta_families().size()));
  EXPECT_GT(d.contact_queries, 24);
  ASSERT_FALSE(d.promises.empty());
  for (const PromiseCheck& p : d.promises) {
    EXPECT_EQ(p.method, "robust");  // the paper's readings and linear-system are n/a at δ
    EXPECT_GT(p.checked, 0) << to_string(p.decision);
    EXPECT_EQ(p.violations, 0) << to_string(p.decision);
  }
  EXPECT_EQ(d.times.size(), 2u);
  EXPECT_EQ(d.truths, d.family_queries);  // every delta- case has its construction's truth
  EXPECT_EQ(d.truth_violations, 0);
  ASSERT_EQ(d.metamorphic.size(), 3u);  // exact, robust, float-cubic
  for (const MetamorphicCheck& m : d.metamorphic) EXPECT_GT(m.checked, 100) << m.method;
  EXPECT_EQ(d.violations(), 0);
  EXPECT_TRUE(c.certified()) << c.first_violation;
  EXPECT_NE(text_of(fs::path(c.options.out_dir) / "certificate.md").find("## Minimum separation"),
            std::string::npos);
  EXPECT_NE(text_of(fs::path(c.options.out_dir) / "certificate.json").find("\"min_distance\""),
            std::string::npos);
}

TEST(CertifyDelta, ZeroSkipsTheStageAndAFixedDIsUsed) {
  const fs::path out = fresh_temp_dir("certify_delta_zero");
  CertifyOptions o = tiny(out);
  o.min_distance = 0;
  EXPECT_FALSE(certify(o).delta.run);
  const fs::path again = fresh_temp_dir("certify_delta_fixed");
  o = tiny(again);
  o.min_distance = 1e-6;
  const Certificate c = certify(o);
  EXPECT_TRUE(c.delta.run);
  EXPECT_EQ(c.delta.delta_words(), "1e-06");
}

}  // namespace
}  // namespace fdh::verify
