// The catalogue's rows for the second hostile probe (issue 22), one class each: links planted at
// every predictable chart name, a full disk under the charts, names and paths that are not
// UTF-8 in every JSON writer, SIGTERM and SIGINT in the middle of a write, the temporaries of a
// dead run, and links in fuzz's work folder. fdhcert runs as a child process, as a user would
// run it.
#include <fcntl.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fdh/io/json_text.hpp"
#include "fdh/os/child_process.hpp"
#include "temp_dir.hpp"
#include "test_data.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

const std::string kProbeScene = FDH_SOURCE_DIR "/corpus/scenes/table.scene";
const std::string kLatin1 = "caf\xe9-\xe0-\xff";  // Latin-1 bytes: not UTF-8

std::string probe_read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct ProbeRun {
  int status = -1;  // the exit status, or 128 + the signal
  std::string out, err;
};

// fdhcert ARGS in CWD, standard output and error captured in files of `logs`. `started` is
// called with the child's PID before it runs fdhcert (which keeps the PID), and may signal it.
struct ProbeChild {
  std::vector<std::string> args;
  fs::path cwd;
  std::function<void(pid_t)> started = {};
};

ProbeRun probe_run(const ProbeChild& c) {
  const fs::path logs = fresh_temp_dir("probe_logs");
  const std::string out_path = (logs / "out").string(), err_path = (logs / "err").string();
  std::vector<std::string> args = c.args;
  args.insert(args.begin(), FDHCERT_BIN);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int gate[2];
  EXPECT_EQ(::pipe(gate), 0);
  const std::string cwd = c.cwd.string();
  ChildProcess run([&] {
    ::close(gate[1]);
    char go;
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0 || ::chdir(cwd.c_str()))
      ::_exit(120);
    if (::read(gate[0], &go, 1) < 0) ::_exit(121);  // 0 at EOF: the parent is ready
    ::execv(argv[0], argv.data());
    return 122;
  });
  ::close(gate[0]);
  if (c.started) c.started(run.pid());
  ::close(gate[1]);
  const int status = run.wait().raw;
  ProbeRun r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = probe_read(out_path);
  r.err = probe_read(err_path);
  return r;
}

bool probe_have(const std::string& program) {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"})
    if (::access((std::string(dir) + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

// Every file under `dir` (recursively) by relative name, with its bytes (a link: "-> target").
std::map<std::string, std::string> probe_snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (e.is_symlink())
      s[rel] = "-> " + fs::read_symlink(e.path()).string();
    else if (e.is_regular_file())
      s[rel] = probe_read(e.path());
  }
  return s;
}

std::vector<std::string> probe_temporaries(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp.") != std::string::npos)
      found.push_back(e.path().string());
  return found;
}

// A PID that no longer runs: a child's, reaped.
pid_t probe_dead_pid() {
  ChildProcess c([] { return 0; });
  const pid_t dead = c.pid();
  c.wait();
  return dead;
}

// --- Charts: links planted at every name a run could predict write nothing outside. ---------

TEST(SecondProbe, LinksAtEveryPredictableChartNameWriteNothingOutside) {
  if (!probe_have("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_temp_dir("probe_chart_links");
  const fs::path victim = dir / "victim", out = dir / "t";
  fs::create_directories(victim);
  fs::create_directories(out / "data");
  std::ofstream(victim / "precious") << "the victim's own\n";
  const std::vector<std::string> outputs = {"table1.md", "table1.png", "table1.svg",
                                            "data/table1.csv", "table1"};
  const auto plant = [&](pid_t pid) {
    for (const std::string& o : outputs)
      for (int n = 0; n < 16; ++n) {
        const std::string name = o + ".tmp." + std::to_string(pid) + "." + std::to_string(n);
        // Half at the victim's file, half dangling (O_CREAT through one would make its target).
        const fs::path target = n % 2 ? victim / "precious" : victim / ("new-" + std::to_string(n));
        fs::create_symlink(target, out / name);
      }
  };
  const auto before = probe_snapshot(victim);
  const ProbeRun r =
      probe_run({{"table1", "--scene", kProbeScene, "--frames", "1", "--out", "t"}, dir, plant});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(probe_snapshot(victim), before) << "a run wrote outside its output folder";
  for (const char* chart : {"table1.png", "table1.svg"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(out / chart))) << chart;
    EXPECT_GT(fs::file_size(out / chart), 1000u) << chart;
  }
}

// --- Charts: a full disk is exit 2 naming it, and the previous charts stay byte-identical. ---

// A small tmpfs mounted for the test (root only), unmounted at the end.
struct ProbeTmpfs {
  fs::path at;
  bool mounted = false;
  ProbeTmpfs(const fs::path& where, const std::string& size) : at(where) {
    fs::create_directories(at);
    mounted =
        ::geteuid() == 0 && ::mount("tmpfs", at.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
  }
  ~ProbeTmpfs() {
    if (mounted) ::umount2(at.c_str(), MNT_DETACH);
  }
  // Fills the file system but `leave` bytes.
  void fill(std::uintmax_t leave) const {
    const std::uintmax_t free = fs::space(at).available;
    std::ofstream f(at / "filler", std::ios::binary);
    const std::string block(4096, 'x');
    for (std::uintmax_t n = 0; n + leave + block.size() <= free; n += block.size()) f << block;
  }
};

class SecondProbeFullDisk : public ::testing::TestWithParam<std::string> {};

TEST_P(SecondProbeFullDisk, IsExit2NamingItAndKeepsThePreviousCharts) {
  if (!probe_have("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_temp_dir("probe_full_disk");
  const ProbeTmpfs disk(dir / "m", "8m");
  if (!disk.mounted) GTEST_SKIP() << "cannot mount a tmpfs (not root, or not allowed)";
  fs::copy_file(fs::path(FDH_SOURCE_DIR) / "corpus/queries/hand-made.vf", dir / "hand-made.vf");
  const std::vector<std::string> args =
      GetParam() == "table1"
          ? std::vector<std::string>{"table1", "--scene", kProbeScene, "--frames",
                                     "1",      "--out",   "m/out"}
          : std::vector<std::string>{"report",   "--quick",    "--per-family", "5",
                                     "--soups",  "2",          "--peer-cases", "20",
                                     "--corpus", dir.string(), "--out",        "m/out"};
  const ProbeRun first = probe_run({args, dir});
  ASSERT_EQ(first.status, 0) << first.err;
  std::map<std::string, std::string> charts;
  for (const auto& e : fs::directory_iterator(dir / "m" / "out"))
    if (e.path().extension() == ".png" || e.path().extension() == ".svg")
      charts[e.path().filename().string()] = probe_read(e.path());
  ASSERT_FALSE(charts.empty());
  disk.fill(24 << 10);
  const ProbeRun second = probe_run({args, dir});
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find("No space left on device"), std::string::npos) << second.err;
  if (GetParam() == "table1") {
    EXPECT_NE(second.err.find("gnuplot failed drawing m/out/table1."), std::string::npos)
        << second.err;
  }
  for (const auto& [name, bytes] : charts)
    EXPECT_EQ(probe_read(dir / "m" / "out" / name), bytes) << name << " changed";
  EXPECT_TRUE(probe_temporaries(dir / "m").empty()) << "a failed run left a temporary";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, SecondProbeFullDisk, ::testing::Values("table1", "report"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// --- Names are bytes: every JSON writer takes names and paths that are not UTF-8. -----------

TEST(SecondProbe, JsonStringIsReversibleAndValidUtf8) {
  std::mt19937 rng(22);
  for (int i = 0; i < 2000; ++i) {
    std::string bytes(std::size_t(rng() % 12), '\0');
    for (char& c : bytes) c = char(rng() % 256);
    if (i % 3 == 0) bytes += "\xee\xbe\x80";  // U+EF80 itself: escaped too, to stay reversible
    const std::string text = json_string(bytes);
    EXPECT_EQ(bytes_of_json_string(text), bytes);
    EXPECT_NO_THROW((void)nlohmann::json(text).dump()) << "not valid UTF-8";
  }
  const std::string utf8 = "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80";
  EXPECT_EQ(json_string(utf8), utf8) << "valid UTF-8 must not change";
  EXPECT_EQ(json_string("\xe9"), "\xee\xbf\xa9");  // byte 0xE9 is U+EFE9
  nlohmann::ordered_json j = {{"name", kLatin1}, {kLatin1, {kLatin1, 1}}};
  const nlohmann::json back = nlohmann::json::parse(json_text(j, "x"));
  EXPECT_EQ(bytes_of_json_string(back["name"].get<std::string>()), kLatin1);
  EXPECT_TRUE(back.contains(json_string(kLatin1)));
}

// Valid JSON by Python's strict reader, and holding `name` by the rule.
void probe_expect_json(const std::string& text, const std::string& what) {
  const fs::path f = fresh_temp_dir("probe_json") / "j.json";
  std::ofstream(f, std::ios::binary) << text;
  if (probe_have("python3")) {
    std::string prog = "python3", flag = "-c",
                code = "import json,sys; json.load(open(sys.argv[1], encoding='utf-8'))",
                arg = f.string();
    char* argv[] = {prog.data(), flag.data(), code.data(), arg.data(), nullptr};
    ChildProcess py([&] {
      ::execvp(argv[0], argv);
      return 127;
    });
    EXPECT_TRUE(py.wait().ok()) << what << ": Python's json refused it";
  }
  EXPECT_TRUE(nlohmann::json::accept(text)) << what;
  EXPECT_NE(text.find(json_string(kLatin1)), std::string::npos) << what << ": no escaped name";
}

TEST(SecondProbe, NamesThatAreNotUtf8GiveValidJson) {
  const fs::path dir = fresh_temp_dir("probe_names");
  fs::create_directories(dir / "scenes");
  fs::create_directories(dir / "corpus");
  fs::copy_file(kData + "static.vf", dir / (kLatin1 + ".vf"));
  fs::copy_file(kData + "static.vf", dir / "corpus" / (kLatin1 + ".vf"));
  {
    std::ifstream in(kProbeScene);
    std::ofstream scene(dir / "scenes" / (kLatin1 + ".scene"));
    for (std::string line; std::getline(in, line);)
      if (line.rfind("frames", 0) != 0 && line.rfind("grid", 0) != 0 && line.rfind("name", 0) != 0)
        scene << line << "\n";
    scene << "name " << kLatin1 << "\nframes 2\ngrid 8\n";
  }
  const std::string scene = "scenes/" + kLatin1 + ".scene";

  ProbeRun r = probe_run({{"classify", "--json", kLatin1 + ".vf"}, dir});
  ASSERT_EQ(r.status, 0) << r.err;
  probe_expect_json(r.out, "classify --json");
  r = probe_run({{"simulate", scene, "--frames", "2", "--json"}, dir});
  ASSERT_EQ(r.status, 0) << r.err;
  probe_expect_json(r.out, "simulate --json");
  r = probe_run({{"table1", "--scene", scene, "--frames", "1", "--json", "--out", kLatin1}, dir});
  ASSERT_EQ(r.status, 0) << r.err;
  probe_expect_json(r.out, "table1 --json");
  r = probe_run({{"scenes", "--scenes", "scenes", "--out", "s-" + kLatin1}, dir});
  ASSERT_EQ(r.status, 0) << r.err;
  probe_expect_json(probe_read(dir / ("s-" + kLatin1) / (kLatin1 + ".json")), "scenes");
  r = probe_run({{"certify", "--quick", "--per-family", "5", "--soups", "2", "--peer-cases", "20",
                  "--corpus", "corpus", "--out", "c-" + kLatin1},
                 dir});
  ASSERT_EQ(r.status, 0) << r.err;
  probe_expect_json(probe_read(dir / ("c-" + kLatin1) / "certificate.json"), "certify");
}

// --- Signals: SIGTERM and SIGINT remove this run's temporaries, then end by the signal. -----

struct ProbeSignalRow {
  std::string name;
  std::vector<std::string> args;
  std::string output;  // its temporary, OUTPUT.tmp.<pid>.<n>, is waited for
  int signal;
};

class SecondProbeSignals : public ::testing::TestWithParam<ProbeSignalRow> {};

TEST_P(SecondProbeSignals, LeaveNothingAndEndByTheSignal) {
  const ProbeSignalRow& row = GetParam();
  const fs::path dir = fresh_temp_dir("probe_signal");
  std::atomic<bool> hit{false};
  std::thread watcher;
  const auto interrupt = [&](pid_t pid) {
    // Once fdhcert has made its temporary (polled while the child starts and runs).
    watcher = std::thread([&, pid] {
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
      while (std::chrono::steady_clock::now() < give_up) {
        std::error_code ec;
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
          if (it->path().filename().string().rfind(row.output + ".tmp.", 0) == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            hit = ::kill(pid, row.signal) == 0;
            return;
          }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    });
  };
  const ProbeRun r = probe_run({row.args, dir, interrupt});
  watcher.join();
  ASSERT_TRUE(hit) << "no temporary appeared: " << r.err;
  EXPECT_EQ(r.status, 128 + row.signal) << r.err;
  EXPECT_TRUE(probe_temporaries(dir).empty()) << "a temporary was left";
  EXPECT_FALSE(fs::exists(dir / row.output)) << "a cut output was published";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, SecondProbeSignals,
                         ::testing::Values(ProbeSignalRow{"simulate_record_sigterm",
                                                          {"simulate", kProbeScene, "--frames",
                                                           "100000", "--record", "rec.vf"},
                                                          "rec.vf",
                                                          SIGTERM},
                                           ProbeSignalRow{"generate_sigint",
                                                          {"generate", "generic-moving", "--count",
                                                           "100000000", "--out", "big.vf"},
                                                          "big.vf",
                                                          SIGINT}),
                         [](const ::testing::TestParamInfo<ProbeSignalRow>& info) {
                           return info.param.name;
                         });

// --- Litter: a later run removes a dead run's temporaries of its own outputs, nothing else. ---

TEST(SecondProbe, DeadRunsTemporariesAreRemovedOthersKept) {
  const fs::path dir = fresh_temp_dir("probe_stale");
  const std::string dead = std::to_string(probe_dead_pid());
  const std::string live = std::to_string(::getpid());
  const std::vector<std::string> removed = {"out.vf.tmp." + dead + ".0",
                                            "out.vf.tmp." + dead + ".17"};
  const std::vector<std::string> kept = {"out.vf.tmp." + live + ".0",    // a live PID
                                         "other.vf.tmp." + dead + ".0",  // another output
                                         "out.vf.tmp." + dead + ".x",    // another pattern
                                         "out.vf.tmp.notapid.0", "out.vf.bak"};
  for (const std::string& n : removed) std::ofstream(dir / n) << "litter\n";
  for (const std::string& n : kept) std::ofstream(dir / n) << "kept\n";
  fs::create_directories(dir / ("out.vf.tmp." + dead + ".aB3dE9"));  // a dead run's chart folder
  std::ofstream(dir / ("out.vf.tmp." + dead + ".aB3dE9") / "out.vf.png") << "litter\n";
  const ProbeRun r = probe_run({{"generate", "angled", "--count", "3", "--out", "out.vf"}, dir});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string& n : removed) EXPECT_FALSE(fs::exists(dir / n)) << n;
  EXPECT_FALSE(fs::exists(dir / ("out.vf.tmp." + dead + ".aB3dE9")));
  for (const std::string& n : kept) EXPECT_EQ(probe_read(dir / n), "kept\n") << n;
}

// --- Links in fuzz's work folder: refused with a message, never followed. --------------------

struct ProbeFuzzLinkRow {
  std::string name;
  std::string link;     // a path under OUT made a link to the victim's folder or file
  bool make_run_first;  // a whole run first, so that run folders and markers exist
};

class SecondProbeFuzzLinks : public ::testing::TestWithParam<ProbeFuzzLinkRow> {};

TEST_P(SecondProbeFuzzLinks, AreRefusedAndNothingOutsideChanges) {
  const ProbeFuzzLinkRow& row = GetParam();
  const fs::path dir = fresh_temp_dir("probe_fuzz_link");
  const fs::path victim = dir / "victim", out = dir / "out";
  fs::create_directories(victim / "tmp");
  std::ofstream(victim / "tmp" / "precious") << "the victim's own\n";
  std::ofstream(victim / "file") << "the victim's file\n";
  const std::vector<std::string> args = {"fuzz",    "--method", "robust", "--family", "angled",
                                         "--count", "40",       "--out",  "out"};
  if (row.make_run_first) {
    ASSERT_EQ(probe_run({args, dir}).status, 0);
  }
  fs::create_directories(out);
  // The path given, or the first of its kind (a run folder, a marker) the run made.
  fs::path at = out / row.link;
  if (row.link == "RUN" || row.link == "MARKER")
    for (const auto& e : fs::recursive_directory_iterator(out / ".fuzz"))
      if ((row.link == "RUN" && e.is_directory() && e.path().filename() != "tmp") ||
          (row.link == "MARKER" && e.path().filename().string().rfind("cases-", 0) == 0))
        at = e.path();
  if (fs::exists(fs::symlink_status(at))) fs::remove_all(at);
  fs::create_directories(at.parent_path());
  const bool to_file = row.link.find("lock") != std::string::npos || row.link == "MARKER" ||
                       row.link.find("manifest") != std::string::npos;
  fs::create_symlink(to_file ? victim / "file" : victim, at);
  const auto before = probe_snapshot(victim);
  const ProbeRun r = probe_run({args, dir});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("is a symbolic link"), std::string::npos) << r.err;
  EXPECT_EQ(probe_snapshot(victim), before) << "fuzz changed the link's target";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, SecondProbeFuzzLinks,
                         ::testing::Values(ProbeFuzzLinkRow{"work_folder", ".fuzz", false},
                                           ProbeFuzzLinkRow{"tmp", ".fuzz/tmp", true},
                                           ProbeFuzzLinkRow{"lock", ".fuzz/lock", true},
                                           ProbeFuzzLinkRow{"run_folder", "RUN", true},
                                           ProbeFuzzLinkRow{"marker", "MARKER", true}),
                         [](const ::testing::TestParamInfo<ProbeFuzzLinkRow>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace fdh::verify
