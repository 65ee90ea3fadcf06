// Plug-in settings (--plugin FILE:key=value,...), the thread-safe flag, --threads with a
// plug-in, --budget and progress off a terminal, with the tunable plug-in
// (tests/verify/plugin/tunable_plugin.c; docs/plugins.md).
#include <dlfcn.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cli_run.hpp"
#include "fdh/io/usage_error.hpp"
#include "fdh/os/child_process.hpp"
#include "fdh/plugin/plugin_argument.hpp"
#include "fdhcert_process.hpp"
#include "temp_dir.hpp"
#include "test_data.hpp"
#include "text_file.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;
const std::string kTunable = FDH_TUNABLE_PLUGIN;

// A folder with `n` copies of one hit query, as a corpus or a query file.
fs::path queries(const std::string& name, int n) {
  const fs::path dir = fresh_temp_dir(name);
  std::ofstream f(dir / "hits.vf");
  for (int i = 0; i < n; ++i)
    f << "vf hit" << i
      << " 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  1\n";
  return dir;
}

// A certify run small enough for a test: the corpus `corpus`, few fuzzed queries and soups.
Args small_certify(const fs::path& corpus, const fs::path& out, const std::string& plugin) {
  return {"certify", "--corpus", corpus.string(), "--out", out.string(), "--per-family", "4",
          "--soups", "1",        "--peer-cases",  "4",     "--plugin",   plugin};
}

TEST(PluginSettings, ArgumentsAreReadAsFileAndSettings) {
  const PluginArgument a = parse_plugin_argument("lib/x.so:tolerance=1e-8,max_itr=1000,empty=");
  EXPECT_EQ(a.file, "lib/x.so");
  EXPECT_EQ(a.settings,
            (PluginSettings{{"tolerance", "1e-8"}, {"max_itr", "1000"}, {"empty", ""}}));
  EXPECT_EQ(parse_plugin_argument("x.so").file, "x.so");
  EXPECT_TRUE(parse_plugin_argument("x.so").settings.empty());
  const PluginArgument colon = parse_plugin_argument("a::b.so:k=v:w");  // '::' is a ':' of FILE
  EXPECT_EQ(colon.file, "a:b.so");
  EXPECT_EQ(colon.settings, (PluginSettings{{"k", "v:w"}}));
  // An existing file is the file, ':' and all.
  const fs::path dir = fresh_temp_dir("plugin_colon");
  const std::string odd = (dir / "odd:name.so").string();
  std::ofstream(odd) << "";
  EXPECT_EQ(parse_plugin_argument(odd).file, odd);
  for (const auto& [arg, words] :
       std::vector<std::pair<std::string, std::string>>{{"x.so:", "no settings after ':'"},
                                                        {"x.so:=1", "has an empty key"},
                                                        {"x.so:delay", "has no '='"},
                                                        {"x.so:a=1,,b=2", "an empty setting"},
                                                        {"x.so:a=1,", "an empty setting"},
                                                        {"x.so:a=1,a=2", "is given twice"},
                                                        {"x.so:a b=1", "is not of a-z"},
                                                        {":a=1", "no file before the settings"}}) {
    try {
      parse_plugin_argument(arg);
      ADD_FAILURE() << arg << " was taken";
    } catch (const UsageError& e) {
      EXPECT_TRUE(has(e.what(), words)) << arg << ": " << e.what();
      EXPECT_TRUE(has(e.what(), "'::'")) << e.what();  // how to write a ':' of FILE
    }
  }
}

// Malformed arguments and refused settings stop the run before any work: exit status 2.
TEST(PluginSettings, MalformedOrRefusedSettingsExitTwo) {
  const std::string file = (queries("plugin_refused", 1) / "hits.vf").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {kTunable + ":colour=red", "cannot take colour=red (it takes delay"},
      {kTunable + ":answer=3", "cannot take answer=3"},
      {kTunable + ":delay=-1", "fdh_plugin_init refused its settings"},
      {kTunable + ":delay", "has no '='"},
      {kTunable + ":=3", "has an empty key"},
      {std::string(FDH_EXAMPLE_PLUGIN) + ":tolerance=1", "it takes no settings"}};
  for (const auto& [plugin, words] : cases) {
    const CliRun r = fdhcert({"classify", file, "--plugin", plugin});
    EXPECT_EQ(r.status, 2) << plugin << ": " << r.err;
    EXPECT_TRUE(has(r.err, words)) << plugin << ": " << r.err;
    EXPECT_EQ(r.out, "");
  }
}

// A setting changes what the plug-in answers (its init function took it), in the probe and the
// run alike, and the certificate records the settings and the flag.
TEST(PluginSettings, ReachTheInitFunctionAndTheCertificate) {
  const fs::path dir = queries("plugin_settings", 3);
  const std::string file = (dir / "hits.vf").string();
  const Args base = {"classify", file, "--methods", "tunable", "--check", "--json", "--plugin"};
  Args right = base, wrong = base;
  right.push_back(kTunable + ":answer=1");
  wrong.push_back(kTunable + ":answer=0");
  const CliRun r = fdhcert(right), w = fdhcert(wrong);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(w.status, 1) << w.err;  // "no" to three hits breaks its conservative promise
  EXPECT_EQ(nlohmann::json::parse(w.out)["methods"]["tunable"]["fn"], 3);
  // The probe's child has the settings too: told to answer garbage, it is refused there.
  Args garbage = base;
  garbage.push_back(kTunable + ":answer=2");
  const CliRun g = fdhcert(garbage);
  EXPECT_EQ(g.status, 3) << g.err;
  EXPECT_TRUE(has(g.err,
                  "plug-in tunable returned 2 (garbage: not 0 or 1) in vertex_face_ccd on "
                  "query 'probe/"))
      << g.err;

  const fs::path out = fresh_temp_dir("plugin_settings_cert");
  const Args args = small_certify(dir, out, kTunable + ":answer=1,thread_safe=1");
  const CliRun c = fdhcert(args);
  ASSERT_EQ(c.status, 0) << c.err;
  const nlohmann::json j = nlohmann::json::parse(text_of(out / "certificate.json"));
  ASSERT_EQ(j["plugins"].size(), 1u);
  EXPECT_EQ(j["plugins"][0]["name"], "tunable");
  EXPECT_EQ(j["plugins"][0]["file"], kTunable);
  EXPECT_EQ(j["plugins"][0]["settings"], nlohmann::json({{"answer", "1"}, {"thread_safe", "1"}}));
  EXPECT_EQ(j["plugins"][0]["thread_safe"], true);
  EXPECT_TRUE(j["complete"]);
  EXPECT_TRUE(has(text_of(out / "certificate.md"),
                  "| `tunable` | `" + kTunable + "` | `answer=1`, `thread_safe=1` | yes |"));
}

// The threads the plug-in's functions were called from in this process, since its last init.
int threads_seen() {
  void* lib = ::dlopen(kTunable.c_str(), RTLD_NOW | RTLD_NOLOAD);
  if (!lib) return -1;
  const auto seen = reinterpret_cast<int (*)()>(::dlsym(lib, "tunable_threads_seen"));
  const int n = seen ? seen() : -1;
  ::dlclose(lib);
  return n;
}

// Declared thread-safe, the plug-in runs on every thread of certify's loops; else on one, and
// --threads says why it is ignored.
TEST(PluginSettings, ThreadSafePlugInsRunOnEveryThread) {
  const fs::path corpus = queries("plugin_threads", 400);
  const fs::path out = fresh_temp_dir("plugin_threads_cert");
  Args safe = small_certify(corpus, out, kTunable + ":thread_safe=1,delay=0.0001");
  safe.insert(safe.end(), {"--threads", "4"});
  const CliRun s = fdhcert(safe);
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_GT(threads_seen(), 1);
  EXPECT_FALSE(has(s.err, "is ignored")) << s.err;

  Args one = small_certify(corpus, out, kTunable);
  one.insert(one.end(), {"--threads", "4"});
  const CliRun o = fdhcert(one);
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(threads_seen(), 1);
  EXPECT_TRUE(has(o.err,
                  "fdhcert: --threads 4 is ignored: plug-in tunable is not declared "
                  "thread-safe (FDH_PLUGIN_THREAD_SAFE"))
      << o.err;
}

// A plug-in that takes 0.5 s a call: certify --quick --budget 8 ends within the budget and a
// little, writes its certificate whole, says what was cut and certifies nothing; its progress
// comes as lines on a standard error that is a file.
TEST(PluginBudget, CertifyEndsWithinItsBudgetAndSaysWhatWasCut) {
  const fs::path out = fresh_temp_dir("plugin_budget");
  const double budget = 8;
  const Ended e = run_fdhcert(
      {"certify", "--quick", "--corpus", FDH_SOURCE_DIR "/corpus", "--out", out.string(),
       "--plugin", kTunable + ":delay=0.5", "--budget", "8", "--progress", "always"},
      out);
  EXPECT_EQ(e.status, 1) << e.err;
  EXPECT_LT(e.seconds, budget + 3) << e.err;  // one call of 0.5 s past it, and the writing
  EXPECT_GT(e.seconds, budget - 0.5);
  EXPECT_TRUE(has(e.out, "NOT CERTIFIED (cut short by --budget)")) << e.out;
  EXPECT_TRUE(has(e.err,
                  "the budget of 8 s ran out, so this is not a certification; cut short: "
                  "corpus: "))
      << e.err;
  const nlohmann::json j = nlohmann::json::parse(text_of(out / "certificate.json"));
  EXPECT_FALSE(j["certified"]);
  EXPECT_FALSE(j["complete"]);
  EXPECT_EQ(j["first_violation"], "");
  EXPECT_EQ(j["budget"]["seconds"], 8.0);
  const nlohmann::json& cuts = j["budget"]["cut_short"];
  ASSERT_GE(cuts.size(), 2u);
  EXPECT_EQ(cuts[0]["stage"], "corpus");
  EXPECT_LT(cuts[0]["done"], cuts[0]["total"]);
  EXPECT_EQ(cuts.back()["stage"], "peers");
  const std::string md = text_of(out / "certificate.md");
  EXPECT_TRUE(has(md, "**Not certified: cut short by the budget**")) << md;
  EXPECT_TRUE(has(md, "corpus: ")) << md;
  EXPECT_TRUE(has(md, "generator families: 0 of ")) << md;
  // Progress: whole lines on a file, never a carriage return.
  EXPECT_TRUE(has(e.err, "certify: corpus: ")) << e.err;
  EXPECT_EQ(e.err.find('\r'), std::string::npos);
}

// fuzz: the budget stops the shrinking of a slow plug-in's case and the workers; the case is
// stored, the cases run are marked, and the same command resumes the rest.
TEST(PluginBudget, FuzzStopsShrinkingAndResumes) {
  const fs::path out = fresh_temp_dir("plugin_budget_fuzz");
  const Args args = {"fuzz", "--method",  "tunable", "--family", "parallel-cross", "--count",
                     "20",   "--threads", "1",       "--out",    out.string(),     "--plugin"};
  Args slow = args;
  slow.insert(slow.end(), {kTunable + ":answer=0,delay=0.2", "--budget", "3"});
  const Ended e = run_fdhcert(slow, out);
  EXPECT_EQ(e.status, 0) << e.err;
  EXPECT_LT(e.seconds, 3 + 2.5) << e.err;
  EXPECT_TRUE(has(e.out, "budget of 3 s spent: stopped after ")) << e.out;
  EXPECT_TRUE(has(e.out, "shrinking: the budget stopped it on 1 case(s)")) << e.out;
  Args fast = args;
  fast.push_back(kTunable + ":answer=0");
  const CliRun r = fdhcert(fast);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.out, "20 cases (")) << r.out;
  EXPECT_FALSE(has(r.out, "budget of")) << r.out;
}

}  // namespace
}  // namespace fdh::verify
