// Messages by promise (issue 24): classify, replay and the certificate say which promise a
// disagreement breaks and which one a promise allows, in the checker's words; and classify
// --time gives each method's per-query thread CPU time (the certificate's words:
// Plugin.CertifyCatchesAPlugInThatBreaksItsPromise). The planted miss comes from
// tests/verify/plugin/miss_plugin.c (conservative but on one query), the late time from
// late_toi_plugin.c (never late but on one query).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"
#include "test_data.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// Three static queries: a hit, a hit whose point starts at x = 0.375 (the plug-ins' MAGIC) and
// a segment beside the triangle (no hit). The miss plug-in misses the second (breaking its
// conservative promise) and says hit on the third (a false alarm its promise allows).
fs::path planted(const std::string& name, bool beside = true) {
  const fs::path file = fresh_temp_dir(name) / "planted.vf";
  std::ofstream out(file);
  out << "vf plain 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  1\n"
         "vf magic 0.375 0.25 1  0 0 0  1 0 0  0 1 0  0.375 0.25 -1  0 0 0  1 0 0  0 1 0  1\n";
  if (beside)
    out << "vf beside 0.75 0.75 1  0 0 0  1 0 0  0 1 0  0.75 0.75 -1  0 0 0  1 0 0  0 1 0  0\n";
  return file;
}

TEST(PromiseMessages, ClassifySaysWhichPromiseBrokeAndWhichDisagreementIsAllowed) {
  const std::string file = planted("promise_classify").string();
  const std::vector<std::string> args = {"classify",      file,        "--plugin",
                                         FDH_MISS_PLUGIN, "--methods", "exact,miss-on-magic"};
  const CliRun r = fdhcert(args);
  EXPECT_EQ(r.status, 0) << r.err;  // without --check, whatever the methods answer
  EXPECT_TRUE(has(
      r.err, "miss-on-magic misses a hit at " + file + ":2 (query magic) (breaks CONSERVATIVE)"))
      << r.err;
  EXPECT_TRUE(has(r.err, "miss-on-magic gives a false alarm at " + file +
                             ":3 (query beside) (allowed: conservative)"))
      << r.err;
  EXPECT_FALSE(has(r.err, "disagrees with exact")) << r.err;

  std::vector<std::string> check = args;
  check.push_back("--check");
  EXPECT_EQ(fdhcert(check).status, 1);
  check.push_back("--json");
  const CliRun j = fdhcert(check);
  EXPECT_EQ(j.status, 1);
  const nlohmann::json m = nlohmann::json::parse(j.out)["methods"]["miss-on-magic"];
  EXPECT_EQ(m["promise"], "conservative");
  EXPECT_EQ(m["against_exact"],
            nlohmann::json({{"misses", 1}, {"false_alarms", 1}, {"broken", 1}, {"allowed", 1}}));
}

// An allowed false alarm alone never fails --check; past ten, they are counted, not named.
TEST(PromiseMessages, ClassifyCountsAllowedFalseAlarmsAfterTen) {
  const fs::path file = fresh_temp_dir("promise_allowed") / "beside.vf";
  std::ofstream out(file);
  for (int i = 0; i < 12; ++i)
    out << "vf beside" << i
        << " 0.75 0.75 1  0 0 0  1 0 0  0 1 0  0.75 0.75 -1  0 0 0  1 0 0  0 1 0  0\n";
  out.close();
  const CliRun r = fdhcert({"classify", file.string(), "--plugin", FDH_MISS_PLUGIN, "--methods",
                            "exact,miss-on-magic", "--check"});
  EXPECT_EQ(r.status, 0) << r.err;
  std::size_t named = 0;
  for (std::size_t at = 0; (at = r.err.find("(allowed: conservative)\n", at)) != std::string::npos;
       ++at)
    ++named;
  EXPECT_EQ(named, 10u) << r.err;
  EXPECT_TRUE(has(r.err, "miss-on-magic: 2 more disagreements with exact (allowed: conservative)"))
      << r.err;
}

TEST(PromiseMessages, ReplayCountsBrokenAndAllowedApartByDirection) {
  const std::string file = planted("promise_replay").string();
  const std::vector<std::string> args = {"replay",    file,
                                         "--plugin",  FDH_MISS_PLUGIN,
                                         "--methods", "exact,paper-literal,miss-on-magic"};
  const CliRun r = fdhcert(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.out,
                  "miss-on-magic: 2 failing; 1 miss (breaks CONSERVATIVE); 1 false alarm "
                  "(allowed: conservative)\n"))
      << r.out;
  EXPECT_TRUE(has(r.out, "    miss-on-magic misses a hit at " + file + ":2 (breaks CONSERVATIVE)"))
      << r.out;
  EXPECT_TRUE(
      has(r.out, "    miss-on-magic gives a false alarm at " + file + ":3 (allowed: conservative)"))
      << r.out;
  // paper-literal promises nothing: its misses are named as such.
  EXPECT_TRUE(has(r.out, "paper-literal answers no where exact says hit at " + file +
                             ":1 (no "
                             "promise)"))
      << r.out;

  std::vector<std::string> json = args;
  json.push_back("--json");
  const nlohmann::json j = nlohmann::json::parse(fdhcert(json).out)["methods"];
  const nlohmann::json& m = j["miss-on-magic"];
  EXPECT_EQ(m["failing"], 2);
  EXPECT_EQ(m["promise"], "conservative");
  EXPECT_EQ(m["misses"], nlohmann::json::array({file + ":2"}));
  EXPECT_EQ(m["false_alarms"], nlohmann::json::array({file + ":3"}));
  EXPECT_EQ(m["broken"], nlohmann::json({{"misses", 1}, {"false_alarms", 0}}));
  EXPECT_EQ(m["allowed"], nlohmann::json({{"misses", 0}, {"false_alarms", 1}}));
  EXPECT_EQ(m["no_promise"], nlohmann::json({{"misses", 0}, {"false_alarms", 0}}));
  EXPECT_EQ(j["paper-literal"]["no_promise"]["misses"], 2);
}

// Times: late breaks never-late, earliness is allowed by it; in classify --toi and replay --toi.
TEST(PromiseMessages, TimesSayLateBreaksAndEarlyIsAllowed) {
  const std::string file = planted("promise_times", false).string();
  const CliRun c = fdhcert(
      {"classify", file, "--plugin", FDH_LATE_TOI_PLUGIN, "--methods", "exact,late-toi", "--toi"});
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_TRUE(has(c.err, "at " + file +
                             ":2 (query magic): late-toi's TOI is late: t_lo = 1 > t* "
                             "~ 0.5 (breaks never-late)"))
      << c.err;
  const std::vector<std::string> args = {
      "replay", file, "--plugin", FDH_LATE_TOI_PLUGIN, "--methods", "exact,late-toi", "--toi"};
  const CliRun r = fdhcert(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.out, file + ":2: late-toi's TOI is late: t_lo = 1 > t* ~ 0.5 (breaks "
                                "never-late)"))
      << r.out;
  EXPECT_TRUE(has(r.out, file + ":1: late-toi's TOI is 0, t* ~ 0.5 (allowed: never-late)"))
      << r.out;
  std::vector<std::string> json = args;
  json.push_back("--json");
  const nlohmann::json t = nlohmann::json::parse(fdhcert(json).out)["toi"]["late-toi"];
  EXPECT_EQ(t["promise"], "never-late");
  EXPECT_EQ(t["broken"], nlohmann::json::array({file + ":2"}));
  EXPECT_EQ(t["allowed"], nlohmann::json::array({file + ":1"}));
}

// classify --time: per method the median, 90th percentile and maximum of its per-query thread
// CPU time, in the table and in --json (no timing asserted beyond their order).
TEST(PromiseMessages, ClassifyTimeGivesMedianP90AndMaxPerMethod) {
  const CliRun table = fdhcert({"classify", kData + "moving.vf", kData + "static.vf", "--methods",
                                "exact,robust,paper-literal", "--time", "--rounds", "2"});
  ASSERT_EQ(table.status, 0) << table.err;
  for (const char* column : {"median ns", "p90 ns", "max ns", "slowest", "ns/query"})
    EXPECT_TRUE(has(table.out, column)) << column << "\n" << table.out;

  const CliRun r = fdhcert({"classify", kData + "moving.vf", "--methods",
                            "exact,robust,paper-literal", "--time", "--rounds", "2", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["cpu_time"]["rounds"], 2);
  for (const char* m : {"exact", "robust"}) {
    const nlohmann::json& t = j["cpu_time"]["methods"][m];
    EXPECT_EQ(t["queries"], 3) << m;
    EXPECT_GT(t["median_ns"].get<double>(), 0) << m;
    EXPECT_LE(t["median_ns"].get<double>(), t["p90_ns"].get<double>()) << m;
    EXPECT_LE(t["p90_ns"].get<double>(), t["max_ns"].get<double>()) << m;
    EXPECT_TRUE(has(t["slowest"].get<std::string>(), "moving.vf:")) << t;
  }
  // The paper's methods take no moving query.
  EXPECT_EQ(j["cpu_time"]["methods"]["paper-literal"]["queries"], 0);
  EXPECT_TRUE(j["cpu_time"]["methods"]["paper-literal"]["max_ns"].is_null());
  EXPECT_TRUE(j["methods"]["robust"].contains("ns_per_query"));  // the wall-clock mean stays
}

TEST(PromiseMessages, ClassifyHelpSaysItsExitStatus) {
  const CliRun r = fdhcert({"classify", "--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(has(r.out, "Exit status: 0 when the table is printed")) << r.out;
  EXPECT_TRUE(has(r.out, "without --check classify exits 0")) << r.out;
  EXPECT_TRUE(has(r.out, "--time")) << r.out;
}

}  // namespace
}  // namespace fdh::verify
