// fdhcert fuzz: the same cases whatever the workers or shards, and a SIGKILL loses nothing.
#include "fdh/suite/fuzz.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "fdh/io/query_io.hpp"

#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

FuzzOptions options(const fs::path& out, int threads) {
  FuzzOptions o;
  o.method = "paper-intended";
  o.family = "parallel-cross";
  o.seed = 7;
  o.count = 1200;
  o.chunk = 100;
  o.threads = threads;
  o.out_dir = out.string();
  return o;
}

// The case files (relative names) and their contents.
std::map<std::string, std::string> cases_in(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (!e.is_regular_file() || rel.rfind(".fuzz", 0) == 0) continue;
    std::ifstream in(e.path());
    std::stringstream ss;
    ss << in.rdbuf();
    out[rel] = ss.str();
  }
  return out;
}

TEST(Fuzz, FindsShrinksAndStoresCasesThatReplayAsFailures) {
  const fs::path d = fresh_temp_dir("fuzz_basic");
  std::ostringstream progress;
  const FuzzSummary s = run_fuzz(options(d, 1), progress);
  EXPECT_EQ(s.cases, 1200);
  EXPECT_GT(s.disagreements, 0);
  ASSERT_FALSE(s.distinct.empty());
  EXPECT_LT(s.distinct.size(), std::size_t(s.disagreements));  // shrinking merges cases
  for (const std::string& f : s.distinct) {
    const Query q = read_native(f).at(0);
    EXPECT_TRUE(q.has_truth());
    EXPECT_TRUE(q.is_static_vf());
  }
}

TEST(Fuzz, SameCasesForAnyWorkerCountAndShards) {
  const fs::path one = fresh_temp_dir("fuzz_one"), two = fresh_temp_dir("fuzz_two"),
                 shards = fresh_temp_dir("fuzz_shards");
  std::ostringstream progress;
  const FuzzSummary a = run_fuzz(options(one, 1), progress);
  const FuzzSummary b = run_fuzz(options(two, 2), progress);
  EXPECT_EQ(a.disagreements, b.disagreements);
  EXPECT_EQ(cases_in(one), cases_in(two));
  long disagreements = 0;
  for (int i = 0; i < 3; ++i) {
    FuzzOptions o = options(shards, 1);
    o.shard = i;
    o.shards = 3;
    disagreements += run_fuzz(o, progress).disagreements;
  }
  EXPECT_EQ(disagreements, a.disagreements);
  EXPECT_EQ(cases_in(shards), cases_in(one));
}

TEST(Fuzz, KilledWithSigkillAndRestartedLosesNothing) {
  const fs::path whole = fresh_temp_dir("fuzz_whole"), killed = fresh_temp_dir("fuzz_killed");
  std::ostringstream progress;
  FuzzOptions o = options(whole, 2);
  o.count = 6000;
  const FuzzSummary expected = run_fuzz(o, progress);

  const std::vector<std::string> argv = {
      FDHCERT_BIN, "fuzz", "--method", "paper-intended", "--family", "parallel-cross",
      "--seed",    "7",    "--count",  "6000",           "--chunk",  "100",
      "--threads", "2",    "--out",    killed.string()};
  const auto start = [&] {
    const pid_t pid = ::fork();
    if (pid == 0) {
      std::vector<char*> a;
      for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
      a.push_back(nullptr);
      const int devnull = ::open("/dev/null", O_WRONLY);
      ::dup2(devnull, 1);
      ::execv(a[0], a.data());
      ::_exit(127);
    }
    return pid;
  };
  // Kill it mid-run: once some chunks are done but not all.
  const pid_t pid = start();
  const fs::path markers = killed / ".fuzz";
  const auto count_markers = [&] {
    long n = 0;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(markers, ec))
      n += e.path().filename().string().rfind("chunk-", 0) == 0;
    return n;
  };
  for (int i = 0; i < 2000 && count_markers() < 5; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const long done_before = count_markers();
  EXPECT_GT(done_before, 0);
  EXPECT_LT(done_before, 60) << "the run finished before it could be killed";
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // workers die with the parent

  // Every file left behind is whole: a case file parses, a temporary is only a temporary.
  for (const auto& [rel, text] : cases_in(killed)) {
    if (rel.find(".tmp.") == std::string::npos) {
      EXPECT_NO_THROW(read_native((killed / rel).string())) << rel;
    }
  }

  const pid_t again = start();
  ::waitpid(again, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(cases_in(killed), cases_in(whole));
  o.out_dir = killed.string();
  const FuzzSummary after = run_fuzz(o, progress);  // all done: reads the markers only
  EXPECT_EQ(after.resumed, 6000);
  EXPECT_EQ(after.disagreements, expected.disagreements);
  EXPECT_EQ(after.distinct.size(), expected.distinct.size());
}

}  // namespace
}  // namespace fdh::verify
