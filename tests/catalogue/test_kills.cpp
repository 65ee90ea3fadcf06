// SIGKILL at random points of `fdhcert certify --quick`, `fdhcert report --quick` (charts
// included) and `fdhcert fuzz`, each a child process with its own --out: every output left is
// whole or absent, temporaries are only where their writer's design puts them (certify's and
// report's: only beside --out, as the private folder of a staged output, which the next run
// removes: fdh/os/output_folder.hpp; never inside it), and a fuzz run
// killed again and again and resumed with other --chunk and --threads ends with exactly the
// cases of an uninterrupted run. Also: a user's files that merely look like temporaries
// survive fuzz's clean-up, and two fuzz runs on one folder do not both run.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fdh/io/peer_case_file.hpp"
#include "fdh/io/query_io.hpp"
#include "temp_dir.hpp"

extern char** environ;

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using KillClock = std::chrono::steady_clock;

fs::path kill_dir(const std::string& name) {
  return fresh_temp_dir(name);
}

std::string kill_slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// fdhcert with `args`, stdout and stderr into files (never into the out folder).
pid_t kill_spawn(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all = {FDHCERT_BIN};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : all) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string out = log.string() + ".out", err = log.string() + ".err";
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int rc = ::posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  EXPECT_EQ(rc, 0) << "cannot start " << FDHCERT_BIN;
  return rc == 0 ? pid : -1;
}

int kill_wait(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

// Runs to the end; the exit status (-1 if killed by a signal).
int kill_run(const std::vector<std::string>& args, const fs::path& log) {
  const int status = kill_wait(kill_spawn(args, log));
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// SIGKILL once `ready` holds (polled every 2 ms) and `delay` more has passed, or when the
// child has ended by itself. True if the kill hit a running child; otherwise `*lasted` is how
// long the child ran on after `ready`.
template <class Ready>
bool kill_when(pid_t pid, Ready ready, std::chrono::microseconds delay, double* lasted = nullptr) {
  int status = 0;
  const auto give_up = KillClock::now() + std::chrono::seconds(60);
  while (!ready() && KillClock::now() < give_up) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto from = KillClock::now(), at = from + delay;
  while (KillClock::now() < at) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      if (lasted) *lasted = std::chrono::duration<double>(KillClock::now() - from).count();
      return false;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  ::kill(pid, SIGKILL);
  status = kill_wait(pid);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

bool kill_ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// What is wrong with the files in `out` after a kill: each output must be whole. Temporaries
// may only be fuzz's (in .fuzz/tmp/), beside an output, `<output>.tmp.<pid>.<n>` as the atomic
// writer names them, or in a chart's private folder `<chart>.tmp.<pid>.XXXXXX`; they are listed
// in `temporaries`.
std::vector<std::string> kill_problems(const fs::path& out, std::vector<std::string>* temporaries) {
  std::vector<std::string> bad;
  static const std::regex beside(R"((.+)\.tmp\.[0-9]+\.[0-9]+)");
  static const std::regex chart_folder(R"((.+)\.tmp\.[0-9]+\.[A-Za-z0-9]{6})");  // mkdtemp's
  static const std::string png_sig("\x89PNG\r\n\x1a\n", 8);
  static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  std::error_code ec;
  for (fs::recursive_directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file()) continue;
    const fs::path& p = it->path();
    const std::string rel = fs::relative(p, out).string(), name = p.filename().string();
    const std::string text = kill_slurp(p);
    const std::string ext = p.extension().string();
    std::smatch m;
    const auto problem = [&](const std::string& what) { bad.push_back(rel + ": " + what); };
    if (rel.rfind(".fuzz/", 0) == 0) {  // fuzz's own folder
      if (rel.rfind(".fuzz/tmp/", 0) == 0) {
        if (temporaries) temporaries->push_back(rel);
      } else if (rel == ".fuzz/lock") {
      } else if (name == "manifest") {
        if (text.rfind("fdhcert fuzz run\n", 0) != 0 || !kill_ends_with(text, "\n"))
          problem("a cut manifest");
      } else if (name.rfind("cases-", 0) == 0) {
        if (text.empty() || !kill_ends_with(text, "\n")) problem("a cut marker");
      } else {
        problem("unexpected in .fuzz");
      }
    } else if (std::regex_match(name, m, beside) ||
               std::regex_match(p.parent_path().filename().string(), chart_folder)) {
      if (temporaries) temporaries->push_back(rel);
    } else if (ext == ".json") {
      try {
        const nlohmann::json j = nlohmann::json::parse(text);
        if (name == "certificate.json" && !j.contains("certified")) problem("no \"certified\"");
      } catch (const std::exception& e) {
        problem(std::string("not JSON: ") + e.what());
      }
    } else if (ext == ".md" || ext == ".csv" || ext == ".obj") {
      if (text.empty() || !kill_ends_with(text, "\n")) problem("empty or cut");
    } else if (ext == ".png") {
      if (text.rfind(png_sig, 0) != 0 || !kill_ends_with(text, iend)) problem("a cut PNG");
    } else if (ext == ".html") {
      if (text.find("</html>") == std::string::npos) problem("a cut HTML page");
    } else if (ext == ".svg") {
      std::string t = text;
      while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
      if (!kill_ends_with(t, "</svg>")) problem("a cut SVG");
    } else if (ext == ".vf") {
      try {
        if (read_native(p.string()).empty()) problem("no query");
      } catch (const std::exception& e) {
        problem(std::string("unreadable: ") + e.what());
      }
    } else if (ext == ".txt") {  // a shrunk peer case (certify's peers/)
      try {
        read_peer_case(p.string());
      } catch (const std::exception& e) {
        problem(std::string("unreadable: ") + e.what());
      }
    } else {
      problem("not an output");
    }
  }
  if (ec) bad.push_back(out.string() + ": " + ec.message());
  return bad;
}

// Names and sizes of the files in `out`: a killed run's children must not write on.
std::map<std::string, std::uintmax_t> kill_snapshot(const fs::path& out) {
  std::map<std::string, std::uintmax_t> s;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file()) s[fs::relative(it->path(), out).string()] = it->file_size();
  return s;
}

// After a kill: wait for the children to die, then check every file, and that nothing changes.
void kill_expect_whole(const fs::path& out, const std::string& what,
                       std::vector<std::string>* temporaries = nullptr) {
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto before = kill_snapshot(out);
  for (const std::string& p : kill_problems(out, temporaries)) ADD_FAILURE() << what << ": " << p;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(kill_snapshot(out), before) << what << ": files changed after the kill";
}

// The private folders of staged outputs beside `out` (OUT.tmp.<pid>.staged-XXXXXX), and what
// else is there named as a temporary of `out`.
std::vector<std::string> kill_beside(const fs::path& out, std::vector<std::string>* others) {
  static const std::regex staged(R"(.+\.tmp\.[0-9]+\.staged-[A-Za-z0-9]{6})");
  std::vector<std::string> found;
  const std::string prefix = out.filename().string() + ".tmp.";
  for (const auto& e : fs::directory_iterator(out.parent_path())) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    (std::regex_match(name, staged) && e.is_directory() ? found : *others).push_back(name);
  }
  return found;
}

// After the kills: an uninterrupted run of `args` into `out` ends well, its outputs whole and
// inside `out` nothing but outputs, and it removes the staged folders the kills left beside.
void kill_expect_cleaned_up(const std::vector<std::string>& args, const fs::path& out,
                            const fs::path& log, const std::string& what) {
  std::vector<std::string> others;
  std::cout << what << ": " << kill_beside(out, &others).size()
            << " staged folders left beside the output by the kills\n";
  EXPECT_TRUE(others.empty()) << what << ": " << others.front();
  ASSERT_EQ(kill_run(args, log), 0) << kill_slurp(log.string() + ".err");
  std::vector<std::string> temporaries;
  for (const std::string& p : kill_problems(out, &temporaries)) ADD_FAILURE() << what << ": " << p;
  EXPECT_TRUE(temporaries.empty()) << what << ": " << temporaries.front();
  EXPECT_TRUE(kill_beside(out, &others).empty()) << what << ": the next run did not clean up";
}

std::mt19937& kill_rng() {
  static std::mt19937 rng(std::random_device{}());
  return rng;
}

std::chrono::microseconds kill_uniform(double lo_s, double hi_s) {
  return std::chrono::microseconds(
      long(1e6 * std::uniform_real_distribution<double>(lo_s, hi_s)(kill_rng())));
}

// A small corpus: the hand-made queries and no scenes, so that a run reaches its writes fast.
fs::path kill_small_corpus() {
  const fs::path d = kill_dir("kills_corpus");
  fs::copy_file(fs::path(FDH_SOURCE_DIR) / "corpus/queries/hand-made.vf", d / "hand-made.vf");
  return d;
}

TEST(Kills, CertifyKilledAnywhereLeavesWholeOutputs) {
  const fs::path corpus = kill_small_corpus(), logs = kill_dir("kills_certify_logs");
  const auto args = [&](const fs::path& out) {
    return std::vector<std::string>{"certify", "--quick",  "--per-family",  "5",     "--soups",
                                    "2",       "--corpus", corpus.string(), "--out", out.string()};
  };
  // Rounds 0-4 start in a fresh folder; 5-9 over a whole certificate, then over what each
  // kill left.
  const fs::path over = kill_dir("kills_certify_over") / "out";
  const auto start = KillClock::now();
  ASSERT_EQ(kill_run(args(over), logs / "certify"), 0) << kill_slurp(logs / "certify.err");
  // Kills anywhere in a run as long as that one.
  const double whole_s = std::chrono::duration<double>(KillClock::now() - start).count();
  std::vector<std::string> temporaries;
  int killed = 0;
  for (int round = 0; round < 10; ++round) {
    const fs::path out =
        round < 5 ? kill_dir("kills_certify_" + std::to_string(round)) / "out" : over;
    fs::create_directories(out);
    const pid_t pid = kill_spawn(args(out), logs / "certify");
    killed += kill_when(
        pid, [] { return true; }, kill_uniform(0, whole_s));
    kill_expect_whole(out, "certify round " + std::to_string(round), &temporaries);
    if (round < 5 && !HasFailure()) fs::remove_all(out.parent_path());
  }
  EXPECT_GT(killed, 0) << "every run ended before its kill";
  EXPECT_TRUE(temporaries.empty()) << "a temporary inside the output: " << temporaries.front();
  kill_expect_cleaned_up(args(over), over, logs / "certify", "certify");
  if (!HasFailure())
    for (const fs::path& d : {corpus, logs, over.parent_path()}) fs::remove_all(d);
}

TEST(Kills, ReportKilledAnywhereAndInItsChartsLeavesWholeOutputs) {
  const fs::path corpus = kill_small_corpus(), logs = kill_dir("kills_report_logs");
  const fs::path out = kill_dir("kills_report") / "out";
  fs::create_directories(out);
  const std::vector<std::string> args = {"report",  "--quick",   "--per-family", "5",
                                         "--soups", "2",         "--corpus",     corpus.string(),
                                         "--out",   out.string()};
  std::vector<std::string> temporaries;
  // Early kills: in the certificate and the measurements.
  for (int round = 0; round < 3; ++round) {
    const pid_t pid = kill_spawn(args, logs / "report");
    kill_when(
        pid, [] { return true; }, kill_uniform(0, 1.0));
    kill_expect_whole(out, "report, early kill " + std::to_string(round), &temporaries);
  }
  // Kills in the chart step (announced on stdout), the second over the first's charts. A
  // run that ends before its kill tells how long the step lasts: a third round, if needed,
  // kills within that.
  int in_charts = 0;
  double charts_s = 1.0;
  for (int round = 0; round < 3 && (round < 2 || in_charts == 0); ++round) {
    const pid_t pid = kill_spawn(args, logs / "report");
    const fs::path log = logs / "report.out";
    in_charts += kill_when(
        pid, [&] { return kill_slurp(log).find("report: charts") != std::string::npos; },
        kill_uniform(0, charts_s), &charts_s);
    kill_expect_whole(out, "report, kill in the charts " + std::to_string(round), &temporaries);
  }
  EXPECT_GT(in_charts, 0) << "no kill hit the chart step";
  EXPECT_TRUE(temporaries.empty()) << "a temporary inside the output: " << temporaries.front();
  kill_expect_cleaned_up(args, out, logs / "report", "report");
  if (!HasFailure())
    for (const fs::path& d : {corpus, logs, out.parent_path()}) fs::remove_all(d);
}

// The case files under `out` (relative names) and their contents; .fuzz/ left out.
std::map<std::string, std::string> kill_cases(const fs::path& out) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    const std::string rel = fs::relative(e.path(), out).string();
    if (e.is_regular_file() && rel.rfind(".fuzz", 0) != 0 && rel.find("notes") == rel.npos)
      m[rel] = kill_slurp(e.path());
  }
  return m;
}

std::vector<std::string> kill_fuzz_args(const fs::path& out, int chunk, int threads,
                                        const std::string& seed = "7",
                                        const std::string& count = "8000") {
  return {"fuzz",
          "--seed",
          seed,
          "--method",
          "paper-intended",
          "--family",
          "parallel-cross",
          "--count",
          count,
          "--chunk",
          std::to_string(chunk),
          "--threads",
          std::to_string(threads),
          "--out",
          out.string(),
          "--json"};
}

TEST(Kills, FuzzKilledAgainAndAgainAndResumedWithOtherOptionsEndsWithTheSameCases) {
  const fs::path whole = kill_dir("kills_fuzz_whole"), killed = kill_dir("kills_fuzz_killed"),
                 logs = kill_dir("kills_fuzz_logs");
  const auto start = KillClock::now();
  ASSERT_EQ(kill_run(kill_fuzz_args(whole, 500, 2), logs / "whole"), 0)
      << kill_slurp(logs / "whole.err");
  // Kills within a run as long as that one: seven rounds of at most 12 % of it each cannot
  // finish the work however fast the machine is, so round 2 is always an unfinished run.
  const double whole_s = std::chrono::duration<double>(KillClock::now() - start).count();
  const nlohmann::json expected = nlohmann::json::parse(kill_slurp(logs / "whole.out"));

  // A user's files that look like temporaries, before the run and in its case folder.
  const fs::path case_dir = killed / "paper-intended" / "parallel-cross";
  fs::create_directories(case_dir);
  const std::vector<fs::path> users = {killed / "notes.tmp.1.2", case_dir / "notes.vf.tmp.3.4"};
  for (const fs::path& u : users) std::ofstream(u) << "the user's own\n";

  const std::vector<std::pair<int, int>> resumes = {{100, 2},  {37, 1}, {250, 2}, {64, 1},
                                                    {1000, 2}, {13, 2}, {400, 1}};
  std::vector<std::string> temporaries;
  int hits = 0;
  for (std::size_t round = 0; round < resumes.size(); ++round) {
    const auto [chunk, threads] = resumes[round];
    const pid_t pid = kill_spawn(kill_fuzz_args(killed, chunk, threads), logs / "killed");
    hits += kill_when(
        pid, [] { return true; }, kill_uniform(0.02 * whole_s, 0.12 * whole_s));
    kill_expect_whole(killed, "fuzz round " + std::to_string(round), &temporaries);
    if (round == 2) {
      // Unfinished: a run with another seed refuses, and changes nothing.
      const auto before = kill_snapshot(killed);
      EXPECT_EQ(kill_run(kill_fuzz_args(killed, 100, 2, "8"), logs / "other"), 2);
      EXPECT_NE(kill_slurp(logs / "other.err").find("unfinished fuzz run with other options"),
                std::string::npos)
          << kill_slurp(logs / "other.err");
      EXPECT_EQ(kill_snapshot(killed), before);
    }
  }
  EXPECT_GT(hits, 2) << "the runs ended before their kills";

  ASSERT_EQ(kill_run(kill_fuzz_args(killed, 77, 2), logs / "last"), 0)
      << kill_slurp(logs / "last.err");
  const nlohmann::json got = nlohmann::json::parse(kill_slurp(logs / "last.out"));
  EXPECT_EQ(got["cases"], expected["cases"]);
  EXPECT_EQ(got["disagreements"], expected["disagreements"]);
  EXPECT_EQ(got["distinct"], expected["distinct"]);
  EXPECT_EQ(kill_cases(killed), kill_cases(whole));
  EXPECT_TRUE(kill_problems(killed, nullptr).empty());
  for (const std::string& t : temporaries)  // fuzz's temporaries are in .fuzz/tmp only
    EXPECT_TRUE(t.rfind(".fuzz/tmp/", 0) == 0 || t.find("notes") != t.npos) << t;
  EXPECT_TRUE(fs::is_empty(killed / ".fuzz" / "tmp")) << "the last run left temporaries";
  for (const fs::path& u : users) EXPECT_EQ(kill_slurp(u), "the user's own\n") << u;
  if (!HasFailure())
    for (const fs::path& d : {whole, killed, logs}) fs::remove_all(d);
}

TEST(Kills, TwoFuzzRunsOnOneFolderDoNotBothRun) {
  const fs::path out = kill_dir("kills_fuzz_two"), logs = kill_dir("kills_two_logs");
  // A run far too long to end by itself.
  const pid_t pid = kill_spawn(kill_fuzz_args(out, 100, 1, "7", "100000000"), logs / "first");
  const bool started = [&] {
    for (int i = 0; i < 5000; ++i) {
      std::error_code ec;
      for (const auto& e : fs::recursive_directory_iterator(out / ".fuzz", ec))
        if (e.path().filename() == "manifest") return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }();
  ASSERT_TRUE(started) << kill_slurp(logs / "first.err");
  EXPECT_EQ(kill_run(kill_fuzz_args(out, 100, 1), logs / "second"), 2);
  EXPECT_NE(kill_slurp(logs / "second.err").find("another fuzz run is using " + out.string()),
            std::string::npos)
      << kill_slurp(logs / "second.err");
  ::kill(pid, SIGKILL);
  kill_wait(pid);
  kill_expect_whole(out, "the first run, killed");
  if (!HasFailure())
    for (const fs::path& d : {out, logs}) fs::remove_all(d);
}

}  // namespace
}  // namespace fdh::verify
