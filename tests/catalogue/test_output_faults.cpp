// The catalogue of output faults (issue 14): outputs are whole or absent, checked before the
// run, never clobber what is not ours, and paths never reach a shell. One row per class, each
// with its command, the expected exit status and a fragment of the message. fdhcert runs as a
// child process here, so that its standard output can be /dev/full or closed.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "fdh/os/child_process.hpp"
#include "fdh/scene/scene_report.hpp"
#include "temp_dir.hpp"
#include "test_data.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

const std::string kOutFaultScene = FDH_SOURCE_DIR "/corpus/scenes/table.scene";

// How the child's standard output is set up.
enum class OutFaultStdout { DevNull, DevFull, Closed };

struct OutFaultRun {
  int status = -1;  // the exit status, or 128 + the signal
  std::string err;
};

struct OutFaultChild {
  std::vector<std::string> args;
  std::string cwd;
  OutFaultStdout out = OutFaultStdout::DevNull;
  rlim_t max_file_size = RLIM_INFINITY;
  std::string path_first;  // a folder put first on PATH (a fake gnuplot), if any
};

std::string out_fault_read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// fdhcert ARGS in CWD, its stderr captured; no shell anywhere.
OutFaultRun out_fault_run(const OutFaultChild& c) {
  const fs::path err_file = fresh_temp_dir("out_fault_stderr") / "err.txt";
  std::vector<std::string> args = c.args;
  args.insert(args.begin(), FDHCERT_BIN);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string err_path = err_file.string();
  ChildProcess run([&] {
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err < 0 || ::dup2(err, STDERR_FILENO) < 0 || ::chdir(c.cwd.c_str()) != 0) ::_exit(120);
    if (c.out == OutFaultStdout::Closed) {
      ::close(STDOUT_FILENO);
    } else {
      const int fd = ::open(c.out == OutFaultStdout::DevFull ? "/dev/full" : "/dev/null", O_WRONLY);
      if (fd < 0 || ::dup2(fd, STDOUT_FILENO) < 0) ::_exit(121);
    }
    if (c.max_file_size != RLIM_INFINITY) {
      const rlimit lim{c.max_file_size, c.max_file_size};
      ::setrlimit(RLIMIT_FSIZE, &lim);
      ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead
    }
    if (!c.path_first.empty()) {
      const char* path = std::getenv("PATH");
      ::setenv("PATH", (c.path_first + ":" + (path ? path : "/usr/bin:/bin")).c_str(), 1);
    }
    ::execv(argv[0], argv.data());
    return 122;
  });
  const int status = run.wait().raw;
  OutFaultRun r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.err = out_fault_read(err_file);
  return r;
}

bool out_fault_have_gnuplot() {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"})
    if (::access((std::string(dir) + "/gnuplot").c_str(), X_OK) == 0) return true;
  return false;
}

// The names of the files under `dir` (recursively) whose name contains `part`.
std::vector<std::string> out_fault_files_named(const fs::path& dir, const std::string& part) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(part) != std::string::npos)
      found.push_back(e.path().string());
  return found;
}

// The files under `dir` (recursively) named exactly `name`.
std::vector<std::string> out_fault_files_called(const fs::path& dir, const std::string& name) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename() == name) found.push_back(e.path().string());
  return found;
}

// One row of the catalogue: how to set the fault up in a fresh folder, the command, what it
// must answer, and what must hold of the folder afterwards.
struct OutFaultRow {
  std::string name;
  std::function<OutFaultChild(const fs::path& dir)> setup;
  int status;
  std::string message;
  std::function<void(const fs::path& dir)> after = {};
};

OutFaultChild out_fault_cmd(const fs::path& dir, std::vector<std::string> args) {
  OutFaultChild c;
  c.args = std::move(args);
  c.cwd = dir.string();
  return c;
}

// The catalogue itself: one row per output fault. A table, so longer than a function should be;
// each row is read alone.
std::vector<OutFaultRow> out_fault_catalogue() {
  const std::string vf = kData + "static.vf";
  const std::vector<std::string> fuzz = {"fuzz",     "--method", "robust",
                                         "--family", "angled",   "--out"};
  const auto with = [](std::vector<std::string> a, std::vector<std::string> b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  return {
      // A device, a FIFO or a folder as an output file: refused, never renamed over.
      {"device_as_output",
       [vf](const fs::path& d) {
         return out_fault_cmd(d, {"classify", vf, "--per-query", "/dev/null"});
       },
       2, "/dev/null: is a device",
       [](const fs::path&) {
         struct stat st {};
         ASSERT_EQ(::stat("/dev/null", &st), 0);
         EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null is no longer a device";
       }},
      {"fifo_as_output",
       [](const fs::path& d) {
         EXPECT_EQ(::mkfifo((d / "pipe").c_str(), 0644), 0);
         return out_fault_cmd(d, {"generate", "angled", "--count", "3", "--out", "pipe"});
       },
       2, "pipe: is a FIFO",
       [](const fs::path& d) {
         struct stat st {};
         ASSERT_EQ(::stat((d / "pipe").c_str(), &st), 0);
         EXPECT_TRUE(S_ISFIFO(st.st_mode));
       }},
      {"folder_as_output_file",
       [vf](const fs::path& d) {
         fs::create_directories(d / "folder");
         return out_fault_cmd(d, {"classify", vf, "--per-query", "folder"});
       },
       2, "folder: is a folder"},
      {"file_as_output_folder",
       [](const fs::path& d) {
         std::ofstream(d / "plain") << "mine\n";
         return out_fault_cmd(d, {"certify", "--quick", "--out", "plain"});
       },
       2, "plain: is not a folder",
       [](const fs::path& d) { EXPECT_EQ(out_fault_read(d / "plain"), "mine\n"); }},
      {"device_inside_output_folder",
       [](const fs::path& d) {
         fs::create_directories(d / "out");
         fs::create_symlink("/dev/null", d / "out" / "certificate.md");
         return out_fault_cmd(d, {"certify", "--quick", "--out", "out"});
       },
       2, "certificate.md: is a device"},
      // Standard output: written in place and checked at exit.
      {"stdout_full",
       [vf](const fs::path& d) {
         OutFaultChild c = out_fault_cmd(d, {"classify", vf});
         c.out = OutFaultStdout::DevFull;
         return c;
       },
       2, "fdhcert: error: standard output: No space left on device"},
      {"stdout_full_json",
       [vf](const fs::path& d) {
         OutFaultChild c = out_fault_cmd(d, {"classify", vf, "--json"});
         c.out = OutFaultStdout::DevFull;
         return c;
       },
       2, "standard output: No space left on device"},
      {"stdout_closed",
       [vf](const fs::path& d) {
         OutFaultChild c = out_fault_cmd(d, {"classify", vf});
         c.out = OutFaultStdout::Closed;
         return c;
       },
       2, "standard output: Bad file descriptor"},
      // Every output checked before the run: a bad --png writes neither --record nor --obj.
      {"bad_png_checked_first",
       [](const fs::path& d) {
         return out_fault_cmd(d, {"simulate", kOutFaultScene, "--frames", "2", "--record", "rec.vf",
                                  "--obj", "frames", "--png", "no-such-dir/x.png"});
       },
       2, "no-such-dir/x.png: cannot write into folder no-such-dir: No such file or directory",
       [](const fs::path& d) {
         EXPECT_FALSE(fs::exists(d / "rec.vf"));
         EXPECT_FALSE(fs::exists(d / "frames"));
       }},
      {"bad_record_checked_first",
       [](const fs::path& d) {
         std::ofstream(d / "a-file") << "x";
         return out_fault_cmd(d, {"simulate", kOutFaultScene, "--frames", "2", "--png", "p.png",
                                  "--record", "a-file/rec.vf"});
       },
       2, "a-file is not a folder",
       [](const fs::path& d) { EXPECT_FALSE(fs::exists(d / "p.png")); }},
      {"table1_out_checked_first",
       [](const fs::path& d) {
         fs::create_directories(d / "t" / "table1.png");
         return out_fault_cmd(d,
                              {"table1", "--scene", kOutFaultScene, "--frames", "1", "--out", "t"});
       },
       2, "table1.png: is a folder",
       [](const fs::path& d) { EXPECT_FALSE(fs::exists(d / "t" / "table1.md")); }},
      // A failed write: the path and the system's reason, and no half-written file.
      {"failed_write_leaves_nothing",
       [](const fs::path& d) {
         OutFaultChild c = out_fault_cmd(
             d, {"generate", "generic-moving", "--count", "20000", "--out", "big.vf"});
         c.max_file_size = 1 << 16;
         return c;
       },
       2, "big.vf: cannot write file: File too large",
       [](const fs::path& d) {
         EXPECT_FALSE(fs::exists(d / "big.vf"));
         EXPECT_TRUE(out_fault_files_named(d, ".tmp.").empty());
       }},
      // A file the run did not create survives: an earlier output a refused run would have
      // replaced, and a user's file that looks like a temporary one.
      {"refused_run_keeps_old_output",
       [](const fs::path& d) {
         std::ofstream(d / "keep.vf") << "# mine\n";
         std::ofstream(d / "keep.vf.tmp.1.0") << "also mine\n";
         return out_fault_cmd(d, {"generate", "angled", "--count", "0", "--out", "keep.vf"});
       },
       2, "--count",
       [](const fs::path& d) {
         EXPECT_EQ(out_fault_read(d / "keep.vf"), "# mine\n");
         EXPECT_EQ(out_fault_read(d / "keep.vf.tmp.1.0"), "also mine\n");
       }},
      {"successful_run_keeps_others_files",
       [](const fs::path& d) {
         std::ofstream(d / "out.vf.tmp.1.0") << "also mine\n";
         std::ofstream(d / "notes.txt") << "mine\n";
         return out_fault_cmd(d, {"generate", "angled", "--count", "3", "--out", "out.vf"});
       },
       0, "",
       [](const fs::path& d) {
         EXPECT_EQ(out_fault_read(d / "out.vf.tmp.1.0"), "also mine\n");
         EXPECT_EQ(out_fault_read(d / "notes.txt"), "mine\n");
         EXPECT_NE(out_fault_read(d / "out.vf").find("angled/2"), std::string::npos);
       }},
      // A chart step that fails leaves the old chart whole, and no temporary file.
      {"failed_chart_keeps_old_chart",
       [](const fs::path& d) {
         fs::create_directories(d / "bin");
         fs::create_directories(d / "t");
         std::ofstream(d / "bin" / "gnuplot") << "#!/bin/sh\nexit 3\n";
         fs::permissions(d / "bin" / "gnuplot", fs::perms::owner_all);
         std::ofstream(d / "t" / "table1.png") << "old chart";
         OutFaultChild c =
             out_fault_cmd(d, {"table1", "--scene", kOutFaultScene, "--frames", "1", "--out", "t"});
         c.path_first = (d / "bin").string();
         return c;
       },
       2, "gnuplot failed drawing t/table1.png: gnuplot ended with exit status 3",
       [](const fs::path& d) {
         EXPECT_EQ(out_fault_read(d / "t" / "table1.png"), "old chart");
         EXPECT_FALSE(fs::exists(d / "t" / "table1.svg"));
         EXPECT_TRUE(out_fault_files_named(d / "t", ".tmp.").empty());
       }},
      // Option values: range-checked, overflow-free, messages short.
      {"shard_count_huge",
       [fuzz, with](const fs::path& d) {
         return out_fault_cmd(d, with(fuzz, {"f", "--shard", "1/100000000000"}));
       },
       2, "1 <= I <= N <= 1000000"},
      {"shard_above_max",
       [fuzz, with](const fs::path& d) {
         return out_fault_cmd(d, with(fuzz, {"f", "--shard", "1/1000001"}));
       },
       2, "1 <= I <= N <= 1000000"},
      {"shard_index_above_count",
       [fuzz, with](const fs::path& d) {
         return out_fault_cmd(d, with(fuzz, {"f", "--shard", "3/2"}));
       },
       2, "1 <= I <= N"},
      {"fuzz_count_above_max",
       [fuzz, with](const fs::path& d) {
         return out_fault_cmd(d, with(fuzz, {"f", "--count", "1000000000001"}));
       },
       2, "--count"},
      {"fuzz_count_overflows_long",
       [fuzz, with](const fs::path& d) {
         return out_fault_cmd(d, with(fuzz, {"f", "--count", "99999999999999999999999"}));
       },
       2, "--count"},
      {"fuzz_threads_zero",
       [fuzz, with](const fs::path& d) {
         return out_fault_cmd(d, with(fuzz, {"f", "--threads", "0"}));
       },
       2, "--threads"},
      {"seed_negative",
       [](const fs::path& d) {
         return out_fault_cmd(d, {"generate", "angled", "--seed", "-1", "--out", "x.vf"});
       },
       2, "--seed"},
      {"kdop_k_wrong",
       [](const fs::path& d) {
         return out_fault_cmd(d, {"simulate", kOutFaultScene, "--k", "7"});
       },
       2, "takes 6, 14, 18 or 26, not '7'"},
      {"long_control_value_is_short_and_escaped",
       [](const fs::path& d) {
         return out_fault_cmd(
             d, {"simulate", kOutFaultScene, "--narrow", "\x1b[31m" + std::string(100000, 'A')});
       },
       2, "\\x1b[31mAAAA", [](const fs::path&) {}},
  };
}

void PrintTo(const OutFaultRow& row, std::ostream* os) {
  *os << row.name;
}

class OutputFaults : public ::testing::TestWithParam<OutFaultRow> {};

TEST_P(OutputFaults, GivesItsStatusAndMessage) {
  const OutFaultRow& row = GetParam();
  const fs::path dir = fresh_temp_dir("out_fault_" + row.name);
  const OutFaultRun r = out_fault_run(row.setup(dir));
  EXPECT_EQ(r.status, row.status) << r.err;
  EXPECT_NE(r.err.find(row.message), std::string::npos) << r.err;
  EXPECT_LT(r.err.size(), 2000u) << "a message echoes its input whole";
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "a raw control byte reached stderr";
  if (row.after) row.after(dir);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, OutputFaults, ::testing::ValuesIn(out_fault_catalogue()),
                         [](const ::testing::TestParamInfo<OutFaultRow>& info) {
                           return info.param.name;
                         });

// JSON never holds a non-finite number: nlohmann would print null, json_text refuses.
TEST(OutputFaultsJson, NonFiniteNumberIsRefusedWithItsPlace) {
  nlohmann::ordered_json j = {{"ok", 1.5}, {"times", {{"total", 2.0}}}};
  EXPECT_EQ(json_text(j, "x"), j.dump(2) + "\n");
  j["times"]["total"] = std::numeric_limits<double>::infinity();
  try {
    json_text(j, "the JSON output");
    ADD_FAILURE() << "an infinity was printed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("/times/total"), std::string::npos) << e.what();
  }
  j["times"]["total"] = 1.0;
  j["list"] = {1.0, std::nan("")};
  EXPECT_THROW(json_text(j, "x"), std::runtime_error);
}

// A crafted output folder runs nothing: gnuplot runs in the folder, whose name never enters
// its script, and the charts are written whole.
class OutputFaultsChartFolder : public ::testing::TestWithParam<std::string> {};

TEST_P(OutputFaultsChartFolder, RunsNothingAndDrawsTheChart) {
  if (!out_fault_have_gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_temp_dir("out_fault_chart");
  const OutFaultRun r = out_fault_run(out_fault_cmd(
      dir, {"table1", "--scene", kOutFaultScene, "--frames", "1", "--out", GetParam()}));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(out_fault_files_called(dir, "PWNED").empty()) << "a crafted folder ran a command";
  EXPECT_FALSE(fs::exists("/tmp/PWNED"));
  const fs::path out = dir / GetParam();
  EXPECT_GT(fs::file_size(out / "table1.png"), 1000u);
  EXPECT_NE(out_fault_read(out / "table1.svg").find("</svg>"), std::string::npos);
  EXPECT_TRUE(out_fault_files_named(dir, ".tmp.").empty()) << "a temporary chart was left";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, OutputFaultsChartFolder,
                         ::testing::Values("x'; system(\"touch PWNED\"); '",
                                           "x\"; system(\"touch PWNED\"); \"", "`touch PWNED`",
                                           "it's", "a\nb; $(touch PWNED)"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return "folder" + std::to_string(info.index);
                         });

}  // namespace
}  // namespace fdh::verify
