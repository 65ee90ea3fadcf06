// The catalogue's rows for slow and broken libraries (issue 34, classes 5 and 8; docs/plugins.md,
// "Slow plug-ins" and "When a plug-in fails"): --budget bounds the plug-ins' start-up probe, a
// plug-in of 2 s a call is probed to the end under the default --plugin-timeout, and a plug-in
// that behaves as Tight Inclusion did through a shim (slow calls, a hang on one query, a time of
// 1e19 on another, a lower-bound time with no upper bound) is certified to the end: every broken
// promise named, counted and saved, the certificate written. fdhcert runs as its own process,
// with a deadline.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fdhcert_process.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"

namespace fdh::verify::slow_plugins {
namespace {

namespace fs = std::filesystem;

const std::string kTunable = FDH_TUNABLE_PLUGIN;
const std::string kTiLike = FDH_TI_LIKE_PLUGIN;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Four queries: a hit (q.vf:1), the hang's (x = 0.375, q.vf:2), an edge-edge hit whose time
// is 1e19 (x = 0.125, q.vf:3) and a miss (q.vf:4).
std::string ti_queries(const fs::path& dir) {
  std::ofstream(dir / "q.vf")
      << "vf q1 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  1\n"
         "vf hang 0.375 0.25 1  0 0 0  1 0 0  0 1 0  0.375 0.25 -1  0 0 0  1 0 0  0 1 0  1\n"
         "ee huge 0.125 0 0  1 0 0  0.5 -1 1  0.5 1 1  0.125 0 0  1 0 0  0.5 -1 -1  0.5 1 -1  1\n"
         "vf miss 2 2 1  0 0 0  1 0 0  0 1 0  2 2 -1  0 0 0  1 0 0  0 1 0  0\n";
  return (dir / "q.vf").string();
}

// Class 8: the run goes on past the hang and the time of 1e19, and ends with a certificate
// that names, counts and saves each.
TEST(SlowPlugins, ATightInclusionLikePlugInIsCertifiedToTheEnd) {
  const fs::path d = fresh_temp_dir("slow_plugins_ti");
  fs::create_directories(d / "corpus");
  const Ended e = run_fdhcert({"certify", "--corpus", (d / "corpus").string(), "--per-family", "0",
                               "--soups", "0", "--peer-cases", "0", "--min-distance", "0", "--out",
                               (d / "out").string(), "--plugin-timeout", "1", "--plugin",
                               kTiLike + ":delay=0.01,hang=0.375,huge=0.125", ti_queries(d)},
                              d, 60);
  ASSERT_EQ(e.status, 1) << e.err;  // violated, not ended by the plug-in (3)
  EXPECT_LT(e.seconds, 30) << e.err;
  EXPECT_TRUE(has(e.out, "VIOLATED: ")) << e.out;
  const std::string file = (d / "q.vf").string();
  EXPECT_TRUE(has(e.err,
                  "ti-like gives no answer in 1 s, the exact twin says hit (breaks "
                  "CONSERVATIVE) (point-triangle) (query hang from " +
                      file + ":2), saved to "))
      << e.err;
  EXPECT_TRUE(has(e.err,
                  "ti-like gives no answer in 1 s (breaks never-late) (vertex-face-toi) "
                  "(query hang from " +
                      file + ":2)"))
      << e.err;
  EXPECT_TRUE(has(e.err,
                  "ti-like's TOI [1e+19, 1e+19] is not a time (not 0 <= t_lo <= t_hi <= "
                  "1) (breaks never-late) (edge-edge-toi) (query huge from " +
                      file + ":3), saved to "))
      << e.err;
  const nlohmann::json j = nlohmann::json::parse(text_of(d / "out" / "certificate.json"));
  EXPECT_FALSE(j["certified"]);
  EXPECT_TRUE(j["complete"]);
  ASSERT_EQ(j["broken_promises"].size(), 3u) << j["broken_promises"];
  for (const auto& b : j["broken_promises"]) {  // each saved, as a case replay can read
    const std::string words = b;
    const std::string saved = words.substr(words.rfind("saved to ") + 9);
    EXPECT_TRUE(fs::exists(saved)) << saved;
  }
  long no_answer = 0, not_a_time = 0, zero = 0;
  for (const auto& p : j["promises"])
    if (p["method"] == "ti-like") no_answer += p["no_answer"].get<long>();
  for (const auto& t : j["times"])
    if (t["method"] == "ti-like") {
      no_answer += t["no_answer"].get<long>(), not_a_time += t["not_a_time"].get<long>();
      zero += t["zero"].get<long>();
      EXPECT_EQ(t["late"], 0);  // its lower bound, with no upper bound, is never late
    }
  EXPECT_EQ(no_answer, 2);  // the verdict and the time on the hang's query
  EXPECT_EQ(not_a_time, 1);
  EXPECT_EQ(zero, 1);  // q1: t_lo = 0 where t* = 1/2
  const std::string md = text_of(d / "out" / "certificate.md");
  EXPECT_TRUE(has(md, "3 kinds of broken promise, each saved with its first case:")) << md;
  EXPECT_TRUE(has(md, "1 not a time, ")) << md;
  EXPECT_TRUE(has(md, "1 zero (" + file + ":1), ")) << md;  // the zero time, named
  EXPECT_TRUE(has(md, "(1 no answer in time)")) << md;
}

// Class 5: `certify --budget 3` with a plug-in of 1 s a call ends near 3 s, its probe cut short
// and said so, where it took 8 s.
TEST(SlowPlugins, TheBudgetCoversTheStartUpProbe) {
  const fs::path d = fresh_temp_dir("slow_plugins_budget");
  const Ended e =
      run_fdhcert({"certify", "--quick", "--corpus", FDH_SOURCE_DIR "/corpus", "--out",
                   (d / "out").string(), "--plugin", kTunable + ":delay=1", "--budget", "3"},
                  d, 30);
  EXPECT_EQ(e.status, 1) << e.err;
  EXPECT_LT(e.seconds, 3 + 1 + 1.5) << e.err;  // one call past it, and the writing
  EXPECT_TRUE(has(e.out, "NOT CERTIFIED (cut short by --budget)")) << e.out;
  EXPECT_TRUE(has(e.err, "cut short: probe of plug-in tunable: ")) << e.err;
  const nlohmann::json j = nlohmann::json::parse(text_of(d / "out" / "certificate.json"));
  ASSERT_FALSE(j["budget"]["cut_short"].empty());
  EXPECT_EQ(j["budget"]["cut_short"][0]["stage"], "probe of plug-in tunable");
}

// Class 5: 2 s a call, 8 calls in the probe: 16 s, past the probe's old 10 s, is no failure.
TEST(SlowPlugins, ATwoSecondPerCallPlugInIsProbedToTheEnd) {
  const fs::path d = fresh_temp_dir("slow_plugins_two_seconds");
  std::ofstream(d / "one.vf")
      << "vf q1 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  1\n";
  const Ended e =
      run_fdhcert({"classify", (d / "one.vf").string(), "--plugin", kTunable + ":delay=2",
                   "--methods", "exact,tunable", "--progress", "always"},
                  d, 60);
  EXPECT_EQ(e.status, 0) << e.err;
  EXPECT_GT(e.seconds, 16) << e.err;
  EXPECT_TRUE(has(e.out, "tunable ")) << e.out;
  EXPECT_TRUE(has(e.err, "classify tunable: 0 of 1 queries")) << e.err;  // classify's progress
}

// Class 8: certify --stages runs the stages asked, in that order, and records them; classify
// --time --toi times each time of impact too.
TEST(SlowPlugins, CertifyRunsTheStagesAskedInTheirOrderAndClassifyTimesBoth) {
  const fs::path d = fresh_temp_dir("slow_plugins_stages");
  const Ended e = run_fdhcert(
      {"certify", "--quick", "--corpus", FDH_SOURCE_DIR "/corpus", "--out", (d / "out").string(),
       "--stages", "families,corpus", "--per-family", "10", "--progress", "always"},
      d, 120);
  ASSERT_EQ(e.status, 0) << e.err;
  const std::size_t families = e.err.find("certify: generator families: ");
  ASSERT_NE(families, std::string::npos) << e.err;
  EXPECT_LT(families, e.err.find("certify: corpus: ")) << e.err;
  EXPECT_TRUE(has(e.err, " queries")) << e.err;  // progress counts queries, not files
  const nlohmann::json j = nlohmann::json::parse(text_of(d / "out" / "certificate.json"));
  EXPECT_EQ(j["stages"], nlohmann::json({"families", "corpus"}));
  EXPECT_GT(j["inputs"]["fuzzed_queries"], 0);
  EXPECT_GT(j["inputs"]["corpus_queries"], 0);
  EXPECT_EQ(j["inputs"]["scenes"], 0);
  EXPECT_EQ(j["inputs"]["soup_pairs"], 0);
  for (const auto& m : j["metamorphic"]) EXPECT_EQ(m["checked"], 0) << m;
  const Ended t = run_fdhcert({"classify", ti_queries(d), "--methods", "robust,float-cubic",
                               "--toi", "--time", "--rounds", "1"},
                              d, 120);
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_TRUE(has(t.out, "robust/toi ")) << t.out;
  EXPECT_TRUE(has(t.out, "float-cubic/toi ")) << t.out;
}

// Class 8: a fuzz run that --budget stopped is paused, not broken: the same --out takes a run
// of another family beside it, and the first run's own command then resumes it.
TEST(SlowPlugins, AFuzzRunCutShortByTheBudgetLetsAnotherFamilyUseTheOut) {
  const fs::path d = fresh_temp_dir("slow_plugins_fuzz");
  const auto fuzz = [&](const std::string& family, const std::string& settings,
                        std::vector<std::string> more) {
    std::vector<std::string> args = {"fuzz", "--method", "tunable", "--family", family};
    const std::vector<std::string> rest = {"--count",   "20",
                                           "--threads", "1",
                                           "--out",     (d / "out").string(),
                                           "--plugin",  kTunable + ":" + settings};
    args.insert(args.end(), rest.begin(), rest.end());
    args.insert(args.end(), more.begin(), more.end());
    return run_fdhcert(args, d, 60);
  };
  const Ended cut = fuzz("parallel-cross", "answer=0,delay=0.2", {"--budget", "2"});
  ASSERT_EQ(cut.status, 0) << cut.err;
  ASSERT_TRUE(has(cut.out, "budget of 2 s spent: stopped after ")) << cut.out;
  const Ended other = fuzz("angled", "answer=0", {});
  EXPECT_EQ(other.status, 0) << other.err;
  EXPECT_TRUE(has(other.out, "20 cases (")) << other.out;
  const Ended resumed = fuzz("parallel-cross", "answer=0", {});
  EXPECT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_TRUE(has(resumed.out, "20 cases (")) << resumed.out;
}

// Class 8: classify --toi asks a plug-in whose time gives its verdict (FDH_PLUGIN_TOI_GIVES_
// VERDICT) once per query, not twice; the tables are the same.
TEST(SlowPlugins, ClassifyAsksATimeThatGivesTheVerdictOncePerQuery) {
  const fs::path d = fresh_temp_dir("slow_plugins_once");
  const std::string queries = ti_queries(d);
  const auto calls = [&](const std::string& once, std::string& out) {
    const fs::path count = d / ("count" + once);
    const Ended e =
        run_fdhcert({"classify", queries, "--methods", "exact,ti-like", "--toi", "--plugin",
                     kTiLike + ":delay=0.01,once=" + once + ",count=" + count.string()},
                    d, 60);
    EXPECT_EQ(e.status, 0) << e.err;
    out = e.out.substr(0, e.out.find("ns/query"));  // the counts, not the times
    return fs::file_size(count);
  };
  std::string twice_out, once_out;
  const auto twice = calls("0", twice_out), once = calls("1", once_out);
  // The 4 verdict calls saved (the probe's are the same; 10 ms a call: one timed pass each).
  EXPECT_EQ(twice - once, 4u);
  EXPECT_EQ(twice_out, once_out);
}

}  // namespace
}  // namespace fdh::verify::slow_plugins
