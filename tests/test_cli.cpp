#include "fdh/cli/cli.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace fdh::verify {
namespace {

const std::string kData = FDH_SOURCE_DIR "/tests/data/";

struct CliRun {
  int status;
  std::string out, err;
};

CliRun fdhcert(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int status = run_cli(args, out, err);
  return {status, out.str(), err.str()};
}

bool file_exists(const std::string& p) {
  return std::ifstream(p).good();
}

TEST(Cli, HelpNamesEveryOption) {
  const CliRun r = fdhcert({"classify", "--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* opt : {"--methods", "--gate", "--json", "--per-query", "--kind", "--check"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  EXPECT_EQ(fdhcert({"--help"}).status, 0);
  EXPECT_EQ(fdhcert({}).status, 2);
  EXPECT_EQ(fdhcert({"frobnicate"}).status, 2);
}

TEST(Cli, ClassifyPrintsOneRowPerMethod) {
  const CliRun r = fdhcert({"classify", kData + "static.vf"});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* m : {"exact", "robust", "paper-literal", "paper-intended", "linear-system"})
    EXPECT_NE(r.out.find(m), std::string::npos) << m;
  EXPECT_NE(r.out.find("ns/query"), std::string::npos);
}

TEST(Cli, ClassifyJson) {
  const CliRun r =
      fdhcert({"classify", kData + "static.vf", "--json", "--methods", "exact,robust"});
  ASSERT_EQ(r.status, 0) << r.err;
  // Three queries carry truth and one does not: the counts mix both.
  EXPECT_EQ(r.out.rfind("{\"queries\": 4, \"static_vf\": 4, \"moving_vf\": 0, \"edge_edge\": 0, "
                        "\"truth\": \"mixed\"",
                        0),
            0u)
      << r.out;
  EXPECT_NE(r.out.find("\"exact\": {\"tp\": 2, \"tn\": 2, \"fp\": 0, \"fn\": 0, \"na\": 0, "
                       "\"ns_per_query\": "),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("paper-literal"), std::string::npos);
}

TEST(Cli, ClassifyMovingShowsNotApplicable) {
  const CliRun r = fdhcert({"classify", kData + "moving.vf", "--json", "--check"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"moving_vf\": 1, \"edge_edge\": 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"robust\": {\"tp\": 2, \"tn\": 1, \"fp\": 0, \"fn\": 0, \"na\": 0"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"paper-literal\": {\"tp\": null, \"tn\": null, \"fp\": null, "
                       "\"fn\": null, \"na\": 3, \"ns_per_query\": null}"),
            std::string::npos)
      << r.out;
  const CliRun table = fdhcert({"classify", kData + "moving.vf", kData + "static.vf"});
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("total: 4 static vertex-face, 1 moving vertex-face, 2 edge-edge"),
            std::string::npos)
      << table.out;
  EXPECT_NE(table.out.find("paper-literal         n/a"), std::string::npos) << table.out;
}

TEST(Cli, PerQueryCsv) {
  const std::string out = ::testing::TempDir() + "per_query.csv";
  std::remove(out.c_str());
  const CliRun r = fdhcert(
      {"classify", kData + "static.vf", "--per-query", out, "--methods", "exact,paper-literal"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(),
            "id,truth,exact,paper-literal,contact,time\n"
            "through-face,1,1,0,face,1/2\nshort,0,0,0,none,\nhexfloat,1,1,0,face,1/2\n"
            "no-truth,0,0,0,none,\n");
}

TEST(Cli, GateRejectsBadK) {
  const CliRun r = fdhcert({"classify", kData + "static.vf", "--gate", "7"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--gate takes 6, 14, 18 or 26"), std::string::npos) << r.err;
}

TEST(Cli, BadInputExitsTwoNamingFileAndLineAndWritesNothing) {
  const std::string out = ::testing::TempDir() + "never.csv";
  std::remove(out.c_str());
  const CliRun r =
      fdhcert({"classify", kData + "static.vf", kData + "bad_number.vf", "--per-query", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("bad_number.vf:3:"), std::string::npos) << r.err;
  EXPECT_FALSE(file_exists(out));
  EXPECT_EQ(fdhcert({"classify", kData + "missing.vf"}).status, 2);
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--bogus"}).status, 2);
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--methods", "exact,nope"}).status, 2);
}

TEST(Cli, CheckPassesOnHandMadeTruth) {
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--check"}).status, 0);
}

// generate writes the same file for the same seed, and classify checks robust = exact on it.
TEST(Cli, GenerateIsDeterministicAndClassifiable) {
  const std::string a = ::testing::TempDir() + "gen_a.vf", b = ::testing::TempDir() + "gen_b.vf";
  for (const std::string& f : {a, b})
    ASSERT_EQ(
        fdhcert({"generate", "generic-moving", "--count", "300", "--seed", "7", "--out", f}).status,
        0);
  std::ifstream fa(a), fb(b);
  std::stringstream sa, sb;
  sa << fa.rdbuf();
  sb << fb.rdbuf();
  EXPECT_EQ(sa.str(), sb.str());
  const CliRun r = fdhcert({"classify", a, "--methods", "exact,robust,float-cubic", "--check"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("moving vertex-face"), std::string::npos) << r.out;
  EXPECT_EQ(fdhcert({"generate", "no-such-family", "--out", a}).status, 2);
  EXPECT_EQ(fdhcert({"generate", "generic-moving"}).status, 2);                       // no --out
  EXPECT_EQ(fdhcert({"generate", "angled", "--count", "20", "--out", b}).status, 0);  // static
}

}  // namespace
}  // namespace fdh::verify
