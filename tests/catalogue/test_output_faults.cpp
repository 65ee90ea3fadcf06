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
#include <map>
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
// File-size limits (RLIMIT_FSIZE) of the rows on multi-file outputs: each lets the run's text
// files through and stops its first picture (PNG), as a disk that fills up part way would.
constexpr rlim_t kOutFaultAuditLimit = 4 << 10;     // audit.json 2 KiB, the picture 5 KiB
constexpr rlim_t kOutFaultChartLimit = 16 << 10;    // table1.md 4 KiB, its chart 50 KiB
constexpr rlim_t kOutFaultReportLimit = 128 << 10;  // CSVs 35 KiB, gnuplot scripts, a chart 140 KiB

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

// Every file and link under `dir` (recursively) by relative name, with its bytes: an output
// folder's whole state.
std::map<std::string, std::string> out_fault_snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = e.path().lexically_relative(dir).string();
    s[rel] = e.is_symlink()        ? "-> " + fs::read_symlink(e.path()).string()
             : e.is_regular_file() ? out_fault_read(e.path())
                                   : "(folder)";
  }
  return s;
}

// What is left beside the output folder `dir` named after it as a temporary (DIR.tmp.*).
std::vector<std::string> out_fault_beside(const fs::path& dir) {
  std::vector<std::string> found;
  const std::string prefix = dir.filename().string() + ".tmp.";
  for (const auto& e : fs::directory_iterator(dir.parent_path()))
    if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path().string());
  return found;
}

// A first, whole run of `args` in `d` (its exit status `status`), whose output folder OUT is
// copied to d/before: a second run that fails must leave OUT exactly so.
void out_fault_first_run(const fs::path& d, const std::vector<std::string>& args, int status,
                         const std::string& out) {
  const OutFaultRun first = out_fault_run(out_fault_cmd(d, args));
  ASSERT_EQ(first.status, status) << first.err;
  std::ofstream(d / out / "notes.txt") << "the user's own\n";
  fs::copy(d / out, d / "before", fs::copy_options::recursive | fs::copy_options::copy_symlinks);
}

// After a failed second run: OUT as the first run left it, byte for byte, and nothing beside.
void out_fault_expect_kept(const fs::path& d, const std::string& out) {
  EXPECT_EQ(out_fault_snapshot(d / out), out_fault_snapshot(d / "before"));
  EXPECT_TRUE(out_fault_beside(d / out).empty()) << out_fault_beside(d / out).front();
}

// Frames of the audit rows: a 2x2 cloth square at height z over an obstacle triangle at z = -1;
// from z = 0 to z = -2 the cloth falls through it.
std::string out_fault_frame(const fs::path& d, const std::string& name, double z) {
  std::ofstream(d / name) << "o cloth\nv 0 0 " << z << "\nv 1 0 " << z << "\nv 1 1 " << z
                          << "\nv 0 1 " << z
                          << "\nf 1 2 3\nf 1 3 4\no obstacles\nv -1 -1 -1\nv 3 -1 -1\n"
                             "v -1 3 -1\nf 5 6 7\n";
  return name;
}

// One of the shipped scenes, cut to `frames` frames, as d/scenes/NAME.
void out_fault_short_scene(const fs::path& d, const std::string& name, int frames) {
  fs::create_directories(d / "scenes");
  std::string text = out_fault_read(kOutFaultScene);
  const std::size_t at = text.find("\nframes ");
  text.replace(at + 1, text.find('\n', at + 1) - at - 1, "frames " + std::to_string(frames));
  std::ofstream(d / "scenes" / name) << text;
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
      // Multi-file outputs are published whole (issue 34): a run that cannot write one of its
      // files (a full disk: RLIMIT_FSIZE, as a child's limit) leaves the earlier output byte for
      // byte, the user's own file in it too, and nothing beside it; into a new folder it leaves
      // no folder at all.
      {"audit_out_full_disk_keeps_the_old_audit",
       [](const fs::path& d) {
         const std::string f0 = out_fault_frame(d, "f0.obj", 0);
         out_fault_first_run(d, {"audit", f0, out_fault_frame(d, "f1.obj", -2), "--out", "out"}, 1,
                             "out");
         OutFaultChild c = out_fault_cmd(
             d, {"audit", f0, out_fault_frame(d, "g1.obj", -3), "--out", "out", "--keep", "1"});
         c.max_file_size = kOutFaultAuditLimit;
         return c;
       },
       2, "out/first-violation.png: cannot write file: File too large",
       [](const fs::path& d) { out_fault_expect_kept(d, "out"); }},
      {"audit_out_full_disk_into_a_new_folder_leaves_none",
       [](const fs::path& d) {
         OutFaultChild c =
             out_fault_cmd(d, {"audit", out_fault_frame(d, "f0.obj", 0),
                               out_fault_frame(d, "f1.obj", -3), "--out", "new", "--keep", "1"});
         c.max_file_size = kOutFaultAuditLimit;
         return c;
       },
       2, "new/first-violation.png: cannot write file: File too large",
       [](const fs::path& d) {
         EXPECT_FALSE(fs::exists(d / "new"));
         EXPECT_TRUE(out_fault_beside(d / "new").empty());
       }},
      {"audit_out_over_an_old_one_replaces_its_own_files_only",
       [](const fs::path& d) {
         const std::string f0 = out_fault_frame(d, "f0.obj", 0);
         out_fault_first_run(d, {"audit", f0, out_fault_frame(d, "f1.obj", -2), "--out", "out"}, 1,
                             "out");
         return out_fault_cmd(d, {"audit", f0, out_fault_frame(d, "g1.obj", 0.5), "--out", "out"});
       },
       0, "",
       [](const fs::path& d) {
         EXPECT_EQ(out_fault_read(d / "out" / "notes.txt"), "the user's own\n");
         EXPECT_FALSE(fs::exists(d / "out" / "cases")) << "the old audit's cases were kept";
         EXPECT_FALSE(fs::exists(d / "out" / "first-violation.png"));
         const auto j = nlohmann::json::parse(out_fault_read(d / "out" / "audit.json"));
         EXPECT_TRUE(j["first_violation"].is_null()) << j.dump();
         EXPECT_TRUE(out_fault_beside(d / "out").empty());
       }},
      {"table1_full_disk_keeps_the_old_table",
       [](const fs::path& d) {
         const std::vector<std::string> args = {
             "table1", "--scene", kOutFaultScene, "--frames", "1", "--out", "t"};
         out_fault_first_run(d, args, 0, "t");
         OutFaultChild c = out_fault_cmd(d, args);
         c.max_file_size = kOutFaultChartLimit;
         return c;
       },
       2, "t/table1.png", [](const fs::path& d) { out_fault_expect_kept(d, "t"); }},
      {"report_full_disk_keeps_the_old_report",
       [](const fs::path& d) {
         fs::create_directories(d / "corpus");
         fs::copy_file(fs::path(FDH_SOURCE_DIR) / "corpus/queries/hand-made.vf",
                       d / "corpus" / "hand-made.vf");
         const std::vector<std::string> args = {"report",   "--quick", "--per-family", "5",
                                                "--soups",  "2",       "--peer-cases", "20",
                                                "--corpus", "corpus",  "--out",        "r"};
         out_fault_first_run(d, args, 0, "r");
         OutFaultChild c = out_fault_cmd(d, args);
         c.max_file_size = kOutFaultReportLimit;
         return c;
       },
       2, "r/speed_accuracy.png", [](const fs::path& d) { out_fault_expect_kept(d, "r"); }},
      // A run that fails part way (a bad second scene) leaves the first scene's old files.
      {"scenes_failing_part_way_keeps_the_old_scenes",
       [](const fs::path& d) {
         out_fault_short_scene(d, "a.scene", 3);
         const std::vector<std::string> args = {"scenes", "--scenes", "scenes", "--out", "s"};
         out_fault_first_run(d, args, 0, "s");
         out_fault_short_scene(d, "a.scene", 4);
         std::ofstream(d / "scenes" / "b.scene") << "grid 25\nnot a scene line\n";
         return out_fault_cmd(d, args);
       },
       2, "b.scene:2", [](const fs::path& d) { out_fault_expect_kept(d, "s"); }},
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
