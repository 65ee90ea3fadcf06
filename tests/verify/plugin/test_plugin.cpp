// Plug-ins through --plugin: the example (verify/plugin/example) runs and is certified like a
// built-in method; plug-ins that cannot load, crash or answer garbage are reported with their
// exit status (docs/plugins.md).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cli_run.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/cli/cli.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/os/child_process.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"
#include "test_data.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

std::string faulty(const std::string& fault) {
  return std::string(FDH_FAULTY_PLUGINS) + "/" + fault + ".so";
}

// A query file whose second query starts its point at x = 0.375, the faulty plug-ins' MAGIC.
fs::path magic_queries(const std::string& name) {
  const fs::path dir = fresh_temp_dir(name), file = dir / "magic.vf";
  std::ofstream(file) << "vf plain 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  "
                         "0 1 0  1\n"
                         "vf magic 0.375 0.25 1  0 0 0  1 0 0  0 1 0  0.375 0.25 -1  0 0 0  1 0 "
                         "0  0 1 0  1\n";
  return file;
}

TEST(Plugin, ClassifyShowsTheExampleBesideTheBuiltInMethods) {
  // A segment that meets the triangle's box but not the triangle: a false alarm of the example.
  const fs::path beside = fresh_temp_dir("plugin_classify") / "beside.vf";
  std::ofstream(beside)
      << "vf beside 0.75 0.75 1  0 0 0  1 0 0  0 1 0  0.75 0.75 -1  0 0 0  1 0 0  "
         "0 1 0  0\n";
  for (const std::vector<std::string>& order :
       {std::vector<std::string>{"--plugin", FDH_EXAMPLE_PLUGIN, "--methods", "exact,aabb"},
        std::vector<std::string>{"--methods", "exact,aabb", "--plugin", FDH_EXAMPLE_PLUGIN}}) {
    std::vector<std::string> args = {
        "classify", kData + "static.vf", kData + "moving.vf", beside.string(), "--json", "--check"};
    args.insert(args.end(), order.begin(), order.end());
    const CliRun r = fdhcert(args);
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    // Conservative: it misses no hit of the exact twin, and says hit at least as often.
    EXPECT_EQ(j["methods"]["aabb"]["fn"], 0);
    EXPECT_GE(j["methods"]["aabb"]["fp"], 1);
    EXPECT_EQ(j["methods"]["aabb"]["na"], 0);
  }
  // Once the run is over, the registry holds the built-in methods only.
  for (const Method& m : all_methods()) EXPECT_NE(m.name, "aabb");
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--methods", "aabb"}).status, 2);
}

TEST(Plugin, CertifyListsTheExampleLikeABuiltInMethod) {
  const fs::path out = fresh_temp_dir("plugin_certify"), corpus = fresh_temp_dir("plugin_corpus");
  fs::copy(FDH_SOURCE_DIR "/corpus/queries", corpus / "queries");
  const CliRun r =
      fdhcert({"certify", "--quick", "--plugin", FDH_EXAMPLE_PLUGIN, "--corpus", corpus.string(),
               "--out", out.string(), "--per-family", "10", "--soups", "1", kData + "moving.vf"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json c = nlohmann::json::parse(text_of(out / "certificate.json"));
  std::set<std::string> decisions;
  for (const auto& p : c["promises"])
    if (p["method"] == "aabb") {
      EXPECT_EQ(p["promise"], "conservative");
      EXPECT_GT(p["checked"], 0);
      EXPECT_EQ(p["violations"], 0);
      decisions.insert(p["decision"].get<std::string>());
    }
  EXPECT_EQ(decisions.size(), 3u);  // point-triangle, vertex-face-ccd, edge-edge-ccd
  EXPECT_EQ(c["kdop_contains_exact"]["6/aabb"]["violations"], 0);
  EXPECT_GT(c["kdop_contains_exact"]["6/aabb"]["boxes"], 0);
  // The tree is fast/'s: its check counts for fdh's boxes, never for a plug-in's.
  EXPECT_EQ(c["tree_no_false_cull"]["6"]["soup_pairs"], 1);
  EXPECT_FALSE(c["tree_no_false_cull"].contains("6/aabb"));
  EXPECT_FALSE(has(text_of(out / "certificate.md"), "every exactly overlapping pair | `aabb`"));
  EXPECT_TRUE(has(text_of(out / "certificate.md"), "`aabb`"));
}

// A plug-in that breaks its promise fails the certificate like a built-in method would.
TEST(Plugin, CertifyCatchesAPlugInThatBreaksItsPromise) {
  const fs::path out = fresh_temp_dir("plugin_broken"), corpus = fresh_temp_dir("plugin_none");
  const CliRun r =
      fdhcert({"certify", "--plugin", faulty("broken-promise"), "--corpus", corpus.string(),
               "--out", out.string(), "--per-family", "5", "--soups", "0", kData + "static.vf"});
  EXPECT_EQ(r.status, 1) << r.err;
  // In the checker's words, which promise broke: on standard error and in the certificate.
  const std::string words =
      "broken-promise says no, the exact twin says hit: misses a hit "
      "(breaks EXACT)";
  EXPECT_TRUE(has(r.err, words)) << r.err;
  EXPECT_TRUE(has(text_of(out / "certificate.md"), "**Violated**: " + words));
  EXPECT_TRUE(has(nlohmann::json::parse(text_of(out / "certificate.json"))["first_violation"]
                      .get<std::string>(),
                  words));
}

TEST(Plugin, ReplayAndFuzzRunThePlugIn) {
  const CliRun replay = fdhcert({"replay", FDH_SOURCE_DIR "/corpus/counterexamples", "--plugin",
                                 FDH_EXAMPLE_PLUGIN, "--methods", "aabb", "--json"});
  ASSERT_EQ(replay.status, 0) << replay.err;
  EXPECT_TRUE(nlohmann::json::parse(replay.out)["methods"].contains("aabb"));

  const fs::path out = fresh_temp_dir("plugin_fuzz");
  const CliRun fuzz = fdhcert({"fuzz", "--plugin", FDH_EXAMPLE_PLUGIN, "--method", "aabb",
                               "--family", "parallel-cross", "--count", "40", "--threads", "1",
                               "--out", out.string(), "--json"});
  ASSERT_EQ(fuzz.status, 0) << fuzz.err;
  const nlohmann::json s = nlohmann::json::parse(fuzz.out);
  EXPECT_EQ(s["method"], "aabb");
  EXPECT_EQ(s["cases"], 40);
  // Its false alarms are found and kept as shrunk cases, as for any method.
  for (const auto& f : s["files"]) EXPECT_TRUE(fs::exists(f.get<std::string>())) << f;
  EXPECT_EQ(s["files"].empty(), s["disagreements"] == 0);
}

// Each refusal names the file and exits 2, with nothing on standard output.
TEST(Plugin, APlugInThatCannotBeUsedIsRefusedWithExitTwo) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {FDH_SOURCE_DIR "/no/such/plugin.so", "cannot load"},
      {FDH_NO_PLUGIN, "exports neither fdh_plugin_v2 nor fdh_plugin_v1"},
      {faulty("wrong-abi"), "ABI version 99, but this fdhcert takes 1 or 2"},
      {faulty("taken-name"), "method name 'robust' is taken"},
      {faulty("path-name"), "its name is not a letter or digit, then"},
  };
  for (const auto& [file, words] : bad) {
    const CliRun r = fdhcert({"classify", kData + "static.vf", "--plugin", file});
    EXPECT_EQ(r.status, 2) << file;
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(has(r.err, "fdhcert: plug-in " + file + ": " + words)) << r.err;
  }
}

// The probe runs the plug-in in a child first: this process lives on and says what happened.
// The same file twice, by two paths: refused as a duplicate, not as a taken name.
TEST(Plugin, TheSameFileGivenTwiceIsRefusedAsADuplicate) {
  const std::string again = std::string(FDH_EXAMPLE_PLUGIN).insert(1, "/");  // "//...": same file
  const CliRun r =
      fdhcert({"classify", kData + "static.vf", "--plugin", FDH_EXAMPLE_PLUGIN, "--plugin", again});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(
      has(r.err, "plug-in " + again + ": given twice: the same file as an earlier --plugin"))
      << r.err;
  // A later run in the same process may load it again.
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--plugin", FDH_EXAMPLE_PLUGIN}).status, 0);
}

TEST(Plugin, AProbedCrashOrGarbageBoxIsReportedWithExitThree) {
  const CliRun crash =
      fdhcert({"classify", kData + "static.vf", "--plugin", faulty("crash-when-probed")});
  EXPECT_EQ(crash.status, 3);
  EXPECT_EQ(crash.out, "");
  EXPECT_TRUE(has(crash.err,
                  "fdhcert: plug-in crash-when-probed crashed (SIGSEGV) in vertex_face_ccd on "
                  "query 'probe/through-triangle': vf probe/through-triangle 0x1p-2 0x1p-2 "
                  "0x1p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0 0x0p+0 0x1p-2 "
                  "0x1p-2 -0x1p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0 "
                  "0x0p+0\n"))
      << crash.err;
  const CliRun bad_box = fdhcert({"certify", "--plugin", faulty("nan-kdop")});
  EXPECT_EQ(bad_box.status, 3);
  EXPECT_TRUE(has(bad_box.err,
                  "fdhcert: plug-in nan-kdop returned slab 0 = [-1e+300, nan] (garbage: "
                  "not finite, or lo > hi) in kdop (k = 6) on 1 points"))
      << bad_box.err;
}

// A query without FILE:LINE (the probe's, the generators') is named by a line of a query file
// that asks it again, every coordinate exact.
TEST(Plugin, AGeneratedQueryIsNamedByAQueryLineThatReadsBackExactly) {
  const CliRun r = fdhcert({"classify", kData + "static.vf", "--plugin", faulty("large-garbage")});
  EXPECT_EQ(r.status, 3);
  const std::string head =
      "fdhcert: plug-in large-garbage returned 7 (garbage: not 0 or 1) in vertex_face_ccd on "
      "query 'probe/extreme-coordinates': ";
  ASSERT_EQ(r.err.rfind(head, 0), 0u) << r.err;
  const fs::path file = fresh_temp_dir("plugin_line") / "asked.vf";
  std::ofstream(file) << r.err.substr(head.size());
  const std::vector<QueryRecord> qs = read_native(file.string());
  ASSERT_EQ(qs.size(), 1u);
  EXPECT_EQ(qs[0].id, "probe/extreme-coordinates");
  const std::array<Vec3, 8> x = {{{1e30, 0.1, -0.0},
                                  {0, 0, 0},
                                  {-1e30, 0, 0},
                                  {0, 1, 0},
                                  {-1e30, -1e30, 5e-324},
                                  {0, 0, 0},
                                  {1, 0, 0},
                                  {0, 1, 0}}};
  EXPECT_EQ(qs[0].query.x, x);
  EXPECT_TRUE(std::signbit(qs[0].query.x[0].z));
}

TEST(Plugin, GarbageOnAQueryNamesItsFileAndLine) {
  const fs::path file = magic_queries("plugin_garbage");
  const CliRun r = fdhcert({"classify", file.string(), "--plugin", faulty("garbage-on-magic")});
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(has(r.err,
                  "fdhcert: plug-in garbage-on-magic returned 7 (garbage: not 0 or 1) in "
                  "vertex_face_ccd on query " +
                      file.string() + ":2"))
      << r.err;
}

// A crash on a query the probe did not ask kills fdhcert itself: it says so on the way out.
TEST(Plugin, ACrashOnAQueryIsReportedBeforeTheProcessEnds) {
  const fs::path file = magic_queries("plugin_crash");
  const fs::path err = file.parent_path() / "stderr.txt";
  const std::vector<std::string> argv = {FDHCERT_BIN, "classify", file.string(), "--plugin",
                                         faulty("crash-on-magic")};
  std::vector<char*> a;
  for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
  a.push_back(nullptr);
  ChildProcess run([&] {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    ::execv(a[0], a.data());
    return 127;
  });
  const ChildStatus status = run.wait();
  ASSERT_TRUE(status.exited());
  EXPECT_EQ(status.exit_code(), 3);
  EXPECT_EQ(text_of(err),
            "fdhcert: plug-in crash-on-magic crashed (SIGSEGV) in vertex_face_ccd "
            "on query " +
                file.string() + ":2\n");
}

// The faulty plug-ins are of ABI version 1, built against that version's header as it shipped
// (tests/verify/plugin/v1/): one that keeps its promise loads and is classified as before, and
// gives no time of impact.
TEST(Plugin, AVersionOnePlugInStillLoads) {
  const CliRun r = fdhcert({"classify", kData + "static.vf", "--plugin", faulty("crash-on-magic"),
                            "--methods", "exact,crash-on-magic", "--json", "--check", "--toi"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["methods"]["crash-on-magic"]["fn"], 0);
  EXPECT_GT(j["methods"]["crash-on-magic"]["tp"], 0);
  EXPECT_TRUE(j["toi"]["methods"].contains("exact"));
  EXPECT_FALSE(j["toi"]["methods"].contains("crash-on-magic"));
}

// The example of ABI version 2 gives a time too: the start of the step, never late.
TEST(Plugin, AVersionTwoPlugInGivesATimeThatIsChecked) {
  const CliRun r =
      fdhcert({"classify", kData + "moving.vf", kData + "static.vf", "--plugin", FDH_EXAMPLE_PLUGIN,
               "--methods", "exact,aabb", "--json", "--toi", "--check"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json t = nlohmann::json::parse(r.out)["toi"]["methods"]["aabb"];
  EXPECT_EQ(t["promise"], "never-late");
  EXPECT_GT(t["checked"], 0);
  EXPECT_EQ(t["late"], 0);
  EXPECT_GT(t["zero"], 0);  // 0 wherever t* > 0
  EXPECT_EQ(t["broken"], 0);
}

// A plug-in whose time is late on one query: certify fails and saves the case.
TEST(Plugin, CertifyCatchesALateTimeAndSavesTheCase) {
  const fs::path file = magic_queries("plugin_late");
  const fs::path out = fresh_temp_dir("plugin_late_out"), corpus = fresh_temp_dir("plugin_late_c");
  const CliRun r =
      fdhcert({"certify", "--plugin", FDH_LATE_TOI_PLUGIN, "--corpus", corpus.string(), "--out",
               out.string(), "--per-family", "5", "--soups", "0", file.string()});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(has(r.err, "late-toi's TOI is late: t_lo = 1 > t* ~ 0.5")) << r.err;
  std::size_t saved = 0;
  for (const auto& e : fs::recursive_directory_iterator(out))
    if (e.is_regular_file() && has(text_of(e.path()), "late-toi's TOI is late")) ++saved;
  EXPECT_GE(saved, 1u);
  const nlohmann::json c = nlohmann::json::parse(text_of(out / "certificate.json"));
  bool listed = false;
  for (const auto& p : c["times"])
    if (p["method"] == "late-toi" && p["decision"] == "vertex-face-toi") {
      listed = true;
      EXPECT_EQ(p["promise"], "never-late");
      EXPECT_EQ(p["late"], 1);
      EXPECT_EQ(p["violations"], 1);
    }
  EXPECT_TRUE(listed);
}

TEST(Plugin, TheFourCommandsTakePlugin) {
  for (const char* cmd : {"classify", "fuzz", "replay", "certify"})
    EXPECT_TRUE(has(fdhcert({cmd, "--help"}).out, "--plugin FILE")) << cmd;
}

// docs/plugins.md shows the example plug-in whole: the text there is the file that is built.
TEST(Plugin, TheDocsShowTheExampleThatIsBuilt) {
  const std::string doc = text_of(FDH_SOURCE_DIR "/docs/plugins.md");
  const std::string open = "```c\n", close = "```\n";
  const std::size_t begin = doc.find(open);
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = doc.find(close, begin + open.size());
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(doc.substr(begin + open.size(), end - begin - open.size()),
            text_of(FDH_SOURCE_DIR "/verify/plugin/example/aabb_plugin.c"));
}

}  // namespace
}  // namespace fdh::verify
