// fdhcert's command line, run in-process: options, exit codes, and the outputs' structure.
#include "fdh/cli/cli.hpp"
#include "test_data.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::json;

bool file_exists(const std::string& p) {
  return std::ifstream(p).good();
}

std::string contents(const std::string& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The keys of a JSON object, in the order printed.
std::vector<std::string> keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> out;
  for (const auto& [k, v] : j.items()) out.push_back(k);
  return out;
}

TEST(Cli, HelpNamesEveryOption) {
  const CliRun r = fdhcert({"classify", "--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "");
  for (const char* opt : {"--methods", "--gate", "--json", "--per-query", "--kind", "--check"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  const CliRun main = fdhcert({"--help"});
  EXPECT_EQ(main.status, 0);
  for (const char* cmd : {"classify", "fuzz", "replay", "generate", "certify", "report", "simulate",
                          "audit", "table1", "peers"})
    EXPECT_NE(main.out.find(cmd), std::string::npos) << cmd;
  EXPECT_EQ(fdhcert({"help"}).out, main.out);
  EXPECT_EQ(fdhcert({"help", "classify"}).out, r.out);
  EXPECT_EQ(fdhcert({}).status, 2);
  EXPECT_EQ(fdhcert({"frobnicate"}).status, 2);
}

// Every command's --help goes to out with status 0, even without its required arguments.
TEST(Cli, EveryCommandHasHelp) {
  for (const char* cmd : {"classify", "fuzz", "replay", "generate", "certify", "report", "simulate",
                          "audit", "table1", "peers"}) {
    const CliRun r = fdhcert({cmd, "--help"});
    EXPECT_EQ(r.status, 0) << cmd << ": " << r.err;
    EXPECT_NE(r.out.find("--"), std::string::npos) << cmd;
  }
}

// A wrong command line: status 2, nothing on out, one short "fdhcert: ..." line on err.
TEST(Cli, UsageErrorsExitTwoWithAShortMessage) {
  const std::vector<std::vector<std::string>> bad = {
      {"frobnicate"},
      {"classify"},
      {"classify", kData + "static.vf", "--bogus"},
      {"classify", kData + "static.vf", "--methods"},
      {"classify", kData + "static.vf", "--kind", "xx"},
      {"fuzz", "--method", "robust", "--family", "angled"},  // no --out
      {"fuzz", "--method", "robust", "--family", "angled", "--out", "x", "--shard", "3/2"},
      {"fuzz", "--method", "robust", "--family", "nope", "--out", "x"},
      {"fuzz", "--method", "float-cubic", "--family", "coplanar", "--out", "x", "--toi-tolerance",
       "0.2"},  // without --toi
      {"fuzz", "--method", "float-cubic", "--family", "coplanar", "--out", "x", "--width", "1e-3"},
      {"fuzz", "--method", "float-cubic", "--family", "coplanar", "--out", "x", "--toi",
       "--toi-tolerance", "-1"},
      {"fuzz", "--method", "float-cubic", "--family", "coplanar", "--out", "x", "--toi",
       "--metamorphic"},
      {"generate", "angled", "--out", "x", "--count", "0"},
      {"generate", "angled", "extra", "--out", "x"},
      {"simulate", kData + "none.scene", "--k", "7"},
      {"simulate", kData + "none.scene", "--thickness", "-1"},
      {"simulate", kData + "none.scene", "--self", "maybe"},
      {"simulate", kData + "none.scene", "--narrow", "nope"},
      {"replay"},
      {"audit"},
      {"audit", "f.obj", "--k", "7"},
      {"audit", "f.obj", "--keep", "0"},
      {"audit", "f.obj", "--threads", "0"},
      {"certify", "--threads", "0"},
      {"certify", "--min-distance", "-1"},
      {"certify", "--min-distance", "1e999"},
      {"fuzz", "--method", "robust", "--family", "angled", "--out", "x", "--min-distance", "nan"},
      {"fuzz", "--method", "robust", "--family", "angled", "--out", "x", "--min-distance", "1mm"},
      {"report", "--threads", "1025"},
  };
  for (const auto& args : bad) {
    const CliRun r = fdhcert(args);
    EXPECT_EQ(r.status, 2) << args.back();
    EXPECT_EQ(r.out, "") << args.back();
    EXPECT_EQ(r.err.rfind("fdhcert: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_NE(fdhcert({"frobnicate"}).err.find("unknown command 'frobnicate'"), std::string::npos);
}

// certify --threads N: the same output, byte for byte, for 1, 2 and 64 threads (more than
// most stages have chunks).
TEST(Cli, CertifyPrintsTheSameForAnyThreadCount) {
  const std::filesystem::path corpus = fresh_temp_dir("cli_certify_threads");
  for (const char* f : {"static.vf", "moving.vf"}) std::filesystem::copy(kData + f, corpus / f);
  const std::string out = (corpus / "out").string();
  std::string first_json, first_out;
  for (const char* threads : {"1", "2", "64"}) {
    const CliRun r = fdhcert({"certify", "--corpus", corpus.string(), "--out", out, "--per-family",
                              "4", "--soups", "3", "--peer-cases", "20", "--threads", threads});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = contents(out + "/certificate.json");
    EXPECT_NE(json.find("\"fuzzed_queries\": 96"), std::string::npos);
    if (first_json.empty()) first_json = json, first_out = r.out;
    EXPECT_EQ(json, first_json) << threads;
    EXPECT_EQ(r.out, first_out) << threads;
  }
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
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keys(j), (std::vector<std::string>{"queries", "static_vf", "moving_vf", "edge_edge",
                                               "truth", "methods", "gate", "files"}));
  // Three queries carry truth and one does not: the counts mix both.
  EXPECT_EQ(j["queries"], 4);
  EXPECT_EQ(j["static_vf"], 4);
  EXPECT_EQ(j["moving_vf"], 0);
  EXPECT_EQ(j["edge_edge"], 0);
  EXPECT_EQ(j["truth"], "mixed");
  EXPECT_EQ(j["gate"], 0);
  EXPECT_EQ(keys(j["methods"]), (std::vector<std::string>{"exact", "robust"}));
  const auto& exact = j["methods"]["exact"];
  EXPECT_EQ(keys(exact), (std::vector<std::string>{"tp", "tn", "fp", "fn", "na", "ns_per_query",
                                                   "promise", "against_exact"}));
  EXPECT_EQ(exact["tp"], 2);
  EXPECT_EQ(exact["tn"], 2);
  EXPECT_EQ(exact["fp"], 0);
  EXPECT_EQ(exact["fn"], 0);
  EXPECT_EQ(exact["na"], 0);
  EXPECT_TRUE(exact["ns_per_query"].is_number());
  ASSERT_EQ(j["files"].size(), 1u);
  EXPECT_EQ(j["files"][0]["file"], kData + "static.vf");
  EXPECT_EQ(j["files"][0]["methods"]["robust"]["tp"], 2);
}

TEST(Cli, ClassifyMovingShowsNotApplicable) {
  const CliRun r = fdhcert({"classify", kData + "moving.vf", "--json", "--check"});
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["moving_vf"], 1);
  EXPECT_EQ(j["edge_edge"], 2);
  EXPECT_EQ(j["methods"]["robust"],
            Json::parse(R"({"tp": 2, "tn": 1, "fp": 0, "fn": 0, "na": 0, "ns_per_query": )" +
                        j["methods"]["robust"]["ns_per_query"].dump() +
                        R"(, "promise": "exact", "against_exact": {"misses": 0,
                            "false_alarms": 0, "broken": 0, "allowed": 0}})"));
  EXPECT_EQ(j["methods"]["paper-literal"],
            Json::parse(R"({"tp": null, "tn": null, "fp": null, "fn": null, "na": 3,
                            "ns_per_query": null, "promise": "none", "against_exact": null})"));
  const CliRun table = fdhcert({"classify", kData + "moving.vf", kData + "static.vf"});
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("total: 4 static vertex-face, 1 moving vertex-face, 2 edge-edge"),
            std::string::npos)
      << table.out;
  EXPECT_NE(table.out.find("paper-literal         n/a"), std::string::npos) << table.out;
}

TEST(Cli, ClassifyTimeRatio) {
  const CliRun r = fdhcert({"classify", kData + "moving.vf", kData + "static.vf", "--json",
                            "--methods", "robust", "--time-ratio", "exact", "--rounds", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  const Json t = Json::parse(r.out)["time_ratio"];
  EXPECT_EQ(t["to"], "exact");
  EXPECT_EQ(t["queries"], 7);
  EXPECT_GT(t["mean_ns"]["robust"].get<double>(), 0);
  EXPECT_GT(t["mean_ns"]["exact"].get<double>(), 0);
  const std::map<std::string, int> per = {
      {"point-triangle", 4}, {"vertex-face-ccd", 1}, {"edge-edge-ccd", 2}};
  for (const auto& [decision, n] : per) {
    const Json& d = t["methods"]["robust"][decision];
    EXPECT_EQ(d["queries"], n) << decision;
    EXPECT_GE(d["max"].get<double>(), d["median"].get<double>()) << decision;
    EXPECT_GT(d["median"].get<double>(), 0) << decision;
    EXPECT_NE(d["worst"].get<std::string>().find(".vf:"), std::string::npos) << decision;
  }
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--time-ratio", "nonesuch"}).status, 2);
}

TEST(Cli, PerQueryCsv) {
  const std::string out = (fresh_temp_dir("cli_per_query") / "per_query.csv").string();
  const CliRun r = fdhcert(
      {"classify", kData + "static.vf", "--per-query", out, "--methods", "exact,paper-literal"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(contents(out),
            "id,truth,exact,paper-literal,contact,time\n"
            "through-face,1,1,0,face,1/2\nshort,0,0,0,none,\nhexfloat,1,1,0,face,1/2\n"
            "no-truth,0,0,0,none,\n");
}

// Moving vertex-face and edge-edge rows take contact and time from exact CCD: "moving" and the
// earliest time, a rational or two rationals around an irrational one; a static-only method
// is n/a there.
TEST(Cli, PerQueryCsvMovingVertexFaceAndEdgeEdge) {
  const std::string out = (fresh_temp_dir("cli_per_query_moving") / "per_query.csv").string();
  const CliRun r = fdhcert({"classify", kData + "moving.vf", "--per-query", out, "--methods",
                            "exact,robust,paper-literal", "--check"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(contents(out),
            "id,truth,exact,robust,paper-literal,contact,time\n"
            "rising,1,1,1,n/a,moving,1/2\n"
            "falling,1,1,1,n/a,moving,1/2\n"
            "passing,0,0,0,n/a,none,\n");

  const CliRun times = fdhcert(
      {"classify", kData + "moving_times.vf", "--per-query", out, "--methods", "exact", "--check"});
  ASSERT_EQ(times.status, 0) << times.err;
  // 1/sqrt(2) lies in the bracket (lo^2 < 1/2 < hi^2, with lo = 1592262918131443 / 2^51);
  // the two ends are 2^-53 apart.
  EXPECT_EQ(contents(out),
            "id,truth,exact,contact,time\n"
            "quarter,1,1,moving,1/4\n"
            "at-start,1,1,moving,0\n"
            "apart,0,0,none,\n"
            "irrational,1,1,moving,"
            "1592262918131443/2251799813685248..6369051672525773/9007199254740992\n");
}

TEST(Cli, GateRejectsBadK) {
  const CliRun r = fdhcert({"classify", kData + "static.vf", "--gate", "7"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--gate: takes 6, 14, 18 or 26"), std::string::npos) << r.err;
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--gate", "18"}).status, 0);
}

TEST(Cli, BadInputExitsTwoNamingFileAndLineAndWritesNothing) {
  const std::string out = (fresh_temp_dir("cli_bad_input") / "never.csv").string();
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

// The exact twin against a wrong stored truth: named on err always, exit 1 only with --check.
TEST(Cli, CheckFailsWhereTheTwinDisagreesWithTheFile) {
  const CliRun r = fdhcert({"classify", kData + "wrong_truth.vf", "--check"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("disagrees with the file's truth at " + kData +
                       "wrong_truth.vf:2 (query wrong-no)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(fdhcert({"classify", kData + "wrong_truth.vf"}).status, 0);
}

// generate writes the same file for the same seed, and classify checks robust = exact on it.
TEST(Cli, GenerateIsDeterministicAndClassifiable) {
  const std::filesystem::path dir = fresh_temp_dir("cli_generate");
  const std::string a = (dir / "gen_a.vf").string(), b = (dir / "gen_b.vf").string();
  for (const std::string& f : {a, b})
    ASSERT_EQ(
        fdhcert({"generate", "generic-moving", "--count", "300", "--seed", "7", "--out", f}).status,
        0);
  EXPECT_EQ(contents(a), contents(b));
  const CliRun r = fdhcert({"classify", a, "--methods", "exact,robust,float-cubic", "--check"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("moving vertex-face"), std::string::npos) << r.out;
  EXPECT_EQ(fdhcert({"generate", "no-such-family", "--out", a}).status, 2);
  EXPECT_EQ(fdhcert({"generate", "generic-moving"}).status, 2);                       // no --out
  EXPECT_EQ(fdhcert({"generate", "angled", "--count", "20", "--out", b}).status, 0);  // static
}

TEST(Cli, FuzzJsonSummary) {
  const std::string dir = fresh_temp_dir("cli_fuzz").string();
  const CliRun r = fdhcert({"fuzz", "--method", "paper-literal", "--family", "angled", "--out", dir,
                            "--count", "100", "--threads", "1", "--shard", "1/2", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keys(j),
            (std::vector<std::string>{"method", "metamorphic", "toi", "family", "seed", "shard",
                                      "first", "last", "cases", "resumed", "disagreements",
                                      "by_direction", "distinct", "files"}));
  EXPECT_EQ(j["method"], "paper-literal");
  EXPECT_EQ(j["shard"], "1/2");
  EXPECT_EQ(j["first"], 0);
  EXPECT_EQ(j["last"], 50);
  EXPECT_EQ(j["cases"], 50);
  EXPECT_EQ(j["distinct"], j["files"].size());
}

TEST(Cli, ReplayJsonNamesFailingCases) {
  const CliRun r = fdhcert({"replay", FDH_SOURCE_DIR "/corpus/counterexamples/paper-literal",
                            "--methods", "exact,paper-literal", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keys(j), (std::vector<std::string>{"cases", "exact_mismatches", "methods"}));
  EXPECT_EQ(j["exact_mismatches"].size(), 0u);
  EXPECT_EQ(j["methods"]["exact"]["failing"], 0);
  // Every stored counterexample of a method still fails it.
  EXPECT_EQ(j["methods"]["paper-literal"]["failing"], j["cases"]);
  EXPECT_EQ(j["methods"]["paper-literal"]["cases"].size(), j["cases"].get<std::size_t>());
}

// Replay --toi re-checks the times: robust's keep their enclosure on every stored case, and
// float-cubic's late ones are named.
TEST(Cli, ReplayTimesOfImpact) {
  const CliRun r = fdhcert({"replay", FDH_SOURCE_DIR "/corpus/counterexamples/float-cubic",
                            "--methods", "exact,robust,float-cubic", "--json", "--toi"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(j["toi"]["robust"]["late"].size(), 0u);
  EXPECT_EQ(j["toi"]["robust"]["broken"].size(), 0u);
  EXPECT_EQ(j["toi"]["exact"]["broken"].size(), 0u);
  EXPECT_GT(j["toi"]["float-cubic"]["late"].size(), 0u);
  EXPECT_EQ(j["toi"]["float-cubic"]["broken"].size(), 0u);  // it promises nothing
}

// classify --toi: a second table, and "toi" in the JSON with each method's counts.
TEST(Cli, ClassifyToiCountsLateZeroAndEarly) {
  const CliRun table = fdhcert({"classify", kData + "moving.vf", "--toi", "--check"});
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("early max"), std::string::npos) << table.out;
  const CliRun r = fdhcert({"classify", kData + "moving.vf", kData + "static.vf", "--toi", "--json",
                            "--width", "0x1p-40", "--check"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto t = nlohmann::ordered_json::parse(r.out)["toi"];
  EXPECT_EQ(t["width"], 0x1p-40);
  EXPECT_EQ(t["files"].size(), 2u);
  // The methods that give a time; the paper's give none.
  EXPECT_EQ(keys(t["methods"]), (std::vector<std::string>{"exact", "robust", "float-cubic"}));
  for (const char* m : {"exact", "robust"}) {
    EXPECT_EQ(t["methods"][m]["promise"], "exact-enclosure");
    EXPECT_EQ(t["methods"][m]["late"], 0);
    EXPECT_EQ(t["methods"][m]["broken"], 0);
    EXPECT_GT(t["methods"][m]["contacts"], 0);
    EXPECT_LE(t["methods"][m]["early_max"], 0x1p-40);
  }
  EXPECT_EQ(t["methods"]["float-cubic"]["promise"], "none");
}

// Issue 11's "done when": fuzz on a moving family finds, shrinks and stores float-cubic's
// failures, and replay shows float-cubic failing on each while exact keeps every stored truth.
TEST(Cli, FuzzFloatCubicOnAMovingFamilyThenReplay) {
  const std::string dir = fresh_temp_dir("cli_fuzz_moving").string();
  const CliRun f = fdhcert({"fuzz", "--method", "float-cubic", "--family", "parallel-edges",
                            "--out", dir, "--count", "300", "--threads", "2", "--json"});
  ASSERT_EQ(f.status, 0) << f.err;
  const auto found = nlohmann::ordered_json::parse(f.out);
  EXPECT_GT(found["disagreements"], 0);
  ASSERT_GT(found["distinct"], 0);
  EXPECT_LT(found["distinct"], found["disagreements"]);  // shrinking merged cases
  const CliRun r = fdhcert({"replay", dir, "--methods", "exact,float-cubic", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(j["cases"], found["distinct"]);
  EXPECT_EQ(j["exact_mismatches"].size(), 0u);
  EXPECT_EQ(j["methods"]["exact"]["failing"], 0);
  EXPECT_EQ(j["methods"]["float-cubic"]["failing"], j["cases"]);
}

TEST(Cli, SimulateJsonFields) {
  const CliRun r = fdhcert({"simulate", FDH_SOURCE_DIR "/corpus/scenes/table.scene", "--grid", "6",
                            "--frames", "5", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keys(j), (std::vector<std::string>{"scene",
                                               "grid",
                                               "particles",
                                               "frames",
                                               "narrow",
                                               "k",
                                               "dt",
                                               "stable_dt",
                                               "dt_reduced",
                                               "skin",
                                               "ms_per_frame",
                                               "candidates",
                                               "collisions",
                                               "fp",
                                               "fn",
                                               "inside",
                                               "crossing",
                                               "self_collision",
                                               "self_queries",
                                               "self_hits",
                                               "self_round_frames",
                                               "self_zone_frames",
                                               "self_zone_particles",
                                               "self_stops",
                                               "self_motion_kept",
                                               "self_crossing",
                                               "self_distance",
                                               "self_repulsions",
                                               "self_distance_min",
                                               "obstacle_distance_min",
                                               "energy_start",
                                               "energy_end"}));
  EXPECT_EQ(keys(j["ms_per_frame"]),
            (std::vector<std::string>{"springs", "refit", "traversal", "narrow", "response", "self",
                                      "collision", "total"}));
  EXPECT_EQ(j["grid"], 6);
  EXPECT_EQ(j["frames"], 5);
  EXPECT_EQ(j["narrow"], "robust");
  EXPECT_EQ(j["k"], 18);
  EXPECT_EQ(j["fp"], 0);
  EXPECT_TRUE(j["self_crossing"].is_null());
  EXPECT_EQ(j["self_distance"], 0);  // no self pass: no gap kept
  EXPECT_TRUE(j["self_distance_min"].is_null());
  EXPECT_GT(j["obstacle_distance_min"].get<double>(), 0);
  const CliRun unchecked = fdhcert({"simulate", FDH_SOURCE_DIR "/corpus/scenes/table.scene",
                                    "--grid", "6", "--frames", "5", "--json", "--no-check"});
  ASSERT_EQ(unchecked.status, 0) << unchecked.err;
  EXPECT_TRUE(Json::parse(unchecked.out)["inside"].is_null());
  EXPECT_TRUE(Json::parse(unchecked.out)["crossing"].is_null());
}

// fdhcert peers: a table with the own rows and each peer's, shrunk cases saved under OUT, the
// corpus's stored cases replayed; --json is certificate.json's "peers" object.
TEST(Cli, PeersPrintsEveryRowAndSavesShrunkCases) {
  const std::string out = fresh_temp_dir("cli_peers").string(), corpus = FDH_SOURCE_DIR "/corpus";
  const CliRun r = fdhcert({"peers", "--cases", "40", "--out", out, "--corpus", corpus});
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* row : {"fdh-18", "kdop16", "kdop24", "dbvt-from-points", "bvh-trimesh-aabb"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row;
  EXPECT_NE(r.out.find(out + "/fcl/kdop16-containment-"), std::string::npos) << r.out;
  const CliRun j = fdhcert({"peers", "--cases", "5", "--keep", "0", "--json", "--out", out});
  EXPECT_EQ(j.status, 0) << j.err;
  EXPECT_EQ(Json::parse(j.out)["rows"][0]["library"], "fdhcert");
}

// The peers' JSON (shrunk case names included) is the same for any thread count.
TEST(Cli, PeersPrintTheSameForAnyThreadCount) {
  const std::string corpus = FDH_SOURCE_DIR "/corpus";
  std::string first;
  for (const char* threads : {"1", "2", "64"}) {
    const std::string out = fresh_temp_dir(std::string("cli_peers_threads_") + threads).string();
    const CliRun r = fdhcert({"peers", "--cases", "30", "--keep", "1", "--json", "--out", out,
                              "--corpus", corpus, "--threads", threads});
    ASSERT_EQ(r.status, 0) << r.err;
    std::string json = r.out;  // the saved cases' folder differs per run: compare past it
    for (std::size_t at; (at = json.find(out)) != std::string::npos;)
      json.replace(at, out.size(), "OUT");
    if (first.empty()) first = json;
    EXPECT_EQ(json, first) << threads;
  }
}

// A bad stored peer case: FILE:LINE, exit status 2, nothing on out.
TEST(Cli, PeersRefusesABadStoredCase) {
  const auto corpus = fresh_temp_dir("cli_peers_bad");
  std::filesystem::create_directories(corpus / "peers" / "fcl");
  std::ofstream(corpus / "peers" / "fcl" / "bad.txt") << "peer fcl kdop16 containment\na 1 2\n";
  const CliRun r = fdhcert({"peers", "--cases", "1", "--keep", "0", "--out",
                            (corpus / "out").string(), "--corpus", corpus.string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("bad.txt:2: a point is `a|b x y z`"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fdh::verify
