// The catalogue of hostile plug-ins (issue 22, docs/plugins.md "When a plug-in fails"): one row
// per way a plug-in can break fdhcert from outside its answers — a constructor that crashes, a
// cut library, another machine's library, exit() at load or in the middle of a run (classify,
// certify, a fuzz worker), prints on standard output, a call that never returns (in classify and
// in a fuzz worker, whose watchdog is its own after the fork). Each row runs
// fdhcert as its own process (the plug-in may end it), with a deadline: it must end with the
// documented status and message well within it, never hang.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fdh/os/child_process.hpp"
#include "fdhcert_process.hpp"
#include "temp_dir.hpp"
#include "test_data.hpp"
#include "text_file.hpp"

namespace fdh::verify::hostile_plugins {
namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

std::string rogue(const std::string& name) {
  return std::string(FDH_ROGUE_PLUGINS) + "/" + name + ".so";
}

// A query file of `n` queries whose query `magic` (1-based, 0: none) starts its point at x =
// 0.375, the rogue plug-ins' MAGIC.
std::string queries(const fs::path& dir, int n, int magic) {
  std::ofstream out(dir / "queries.vf");
  for (int i = 1; i <= n; ++i) {
    const char* x = i == magic ? "0.375" : "0.25";
    out << "vf q" << i << ' ' << x << " 0.25 1  0 0 0  1 0 0  0 1 0  " << x
        << " 0.25 -1  0 0 0  1 0 0  0 1 0  1\n";
  }
  return (dir / "queries.vf").string();
}

// One hostile plug-in: the command (made in `dir`), the exit status, fragments its standard
// error must hold (FILE stands for the query file made), and the deadline.
struct Row {
  const char* name;
  std::function<Args(const fs::path& dir)> args;
  int status;
  std::vector<std::string> fragments;
  double deadline = 30;
  bool json_out = false;  // standard output must be one JSON document
};

void PrintTo(const Row& row, std::ostream* os) {
  *os << row.name;
}

// A copy of the example plug-in cut to its first `bytes`.
std::string cut_library(const fs::path& dir, std::size_t bytes) {
  const std::string whole = text_of(FDH_EXAMPLE_PLUGIN);
  std::ofstream(dir / "cut.so", std::ios::binary) << whole.substr(0, bytes);
  return (dir / "cut.so").string();
}

// An ELF header of a 64-bit little-endian aarch64 shared library (e_machine 183), zeros after.
std::string aarch64_library(const fs::path& dir) {
  std::string h(4096, '\0');
  h.replace(0, 4,
            "\x7f"
            "ELF");
  h[4] = 2, h[5] = 1, h[6] = 1;  // ELFCLASS64, ELFDATA2LSB, EV_CURRENT
  h[16] = 3;                     // ET_DYN
  h[18] = char(183);             // EM_AARCH64
  std::ofstream(dir / "arm.so", std::ios::binary) << h;
  return (dir / "arm.so").string();
}

// The catalogue itself. A table, so longer than a function should be; each row is read alone.
const std::vector<Row>& rows() {
  const std::string stat = kData + "static.vf";
  static const std::vector<Row> r = {
      {"ConstructorCrashes",
       [stat](const fs::path&) {
         return Args{"classify", stat, "--plugin", rogue("crash-at-load")};
       },
       2,
       {"fdhcert: plug-in " + rogue("crash-at-load") +
        ": cannot load: crashed (SIGSEGV) in dlopen (its constructors) (docs/plugins.md)\n"}},
      {"CutLibraryAtHalf",
       [stat](const fs::path& d) {
         return Args{"classify", stat, "--plugin",
                     cut_library(d, std::size_t(fs::file_size(FDH_EXAMPLE_PLUGIN) / 2))};
       },
       2,
       {"cut.so: cannot load: "}},
      {"CutLibraryAfterItsHeaders",
       [stat](const fs::path& d) {
         return Args{"classify", stat, "--plugin", cut_library(d, 600)};
       },
       2,
       {"cut.so: cannot load: "}},
      {"AnotherMachinesLibrary",
       [stat](const fs::path& d) {
         return Args{"classify", stat, "--plugin", aarch64_library(d)};
       },
       2,
       {"arm.so: cannot load: it is built for 64-bit aarch64 (ELF machine 183), but this "
        "fdhcert runs on 64-bit x86-64 (dlerror: "}},
      {"ExitAtLoad",
       [stat](const fs::path&) {
         return Args{"classify", stat, "--plugin", rogue("exit-at-load")};
       },
       2,
       {"fdhcert: plug-in " + rogue("exit-at-load") +
        ": cannot load: called exit() in dlopen (its constructors) before the run finished"}},
      {"ExitOnThe200thCallOfClassify",
       [](const fs::path& d) {
         return Args{"classify", queries(d, 300, 0), "--plugin", rogue("exit-on-200"), "--json"};
       },
       3,
       {"fdhcert: plug-in exit-on-200 called exit() in vertex_face_ccd on query FILE:",
        " before the run finished\n"}},
      {"ExitOnThe200thCallOfCertify",
       [](const fs::path& d) {
         fs::create_directories(d / "corpus");
         return Args{"certify",
                     "--plugin",
                     rogue("exit-on-200"),
                     "--corpus",
                     (d / "corpus").string(),
                     "--out",
                     (d / "out").string(),
                     "--per-family",
                     "20",
                     "--soups",
                     "0",
                     queries(d, 300, 0)};
       },
       3,
       {"fdhcert: plug-in exit-on-200 called exit() in ", " before the run finished\n"}},
      {"ExitInAFuzzWorker",
       [](const fs::path& d) {
         return Args{"fuzz",
                     "--plugin",
                     rogue("exit-on-200"),
                     "--method",
                     "exit-on-200",
                     "--family",
                     "parallel-cross",
                     "--count",
                     "2000",
                     "--threads",
                     "1",
                     "--out",
                     (d / "out").string()};
       },
       2,
       {"fdhcert: plug-in exit-on-200 called exit() in vertex_face_ccd on query '",
        "fuzz: a worker of method exit-on-200 ended with exit status 3 (its message is above)"}},
      {"PrintsOnStandardOutput",
       [stat](const fs::path&) {
         return Args{"classify", stat, "--plugin", rogue("prints"), "--json"};
       },
       0,
       {"hello from the plug-in's constructor\n", "printf from the plug-in\n",
        "write(1) from the plug-in\n"},
       30,
       true},
      {"HangsOnAQuery",
       [](const fs::path& d) {
         return Args{"classify", queries(d, 3, 2), "--plugin-timeout",
                     "1",        "--plugin",       rogue("hang-on-magic")};
       },
       3,
       {"fdhcert: plug-in hang-on-magic did not return within 1 s (--plugin-timeout) in "
        "vertex_face_ccd on query FILE:2\n"},
       4},
      {"HangsInAFuzzWorker",
       [](const fs::path& d) {
         return Args{
             "fuzz",     "--plugin-timeout", "1",        "--plugin",       rogue("hang-on-300"),
             "--method", "hang-on-300",      "--family", "parallel-cross", "--count",
             "2000",     "--threads",        "1",        "--out",          (d / "out").string()};
       },
       2,
       {"fdhcert: plug-in hang-on-300 did not return within 1 s (--plugin-timeout) in "
        "vertex_face_ccd on query 'parallel-cross': vf parallel-cross ",
        "fuzz: a worker of method hang-on-300 ended with exit status 3 (its message is above)"},
       10},
      {"HangsOnAQueryUnderTheDefaultLimit",
       [](const fs::path& d) {
         return Args{"classify", queries(d, 3, 2), "--plugin", rogue("hang-on-magic")};
       },
       3,
       {"did not return within 5 s (--plugin-timeout) in vertex_face_ccd on query FILE:2\n"},
       9},
  };
  return r;
}

class HostilePlugins : public ::testing::TestWithParam<Row> {};

TEST_P(HostilePlugins, EndWithTheDocumentedStatusAndMessage) {
  const Row& row = GetParam();
  const fs::path dir = fresh_temp_dir(std::string("hostile_") + row.name);
  const Args args = row.args(dir);
  const Ended e = run_fdhcert(args, dir, row.deadline);
  ASSERT_EQ(e.status, row.status) << "after " << e.seconds << " s\n" << e.err;
  EXPECT_LT(e.seconds, row.deadline);
  const std::string file = (dir / "queries.vf").string();
  for (std::string f : row.fragments) {
    if (const std::size_t at = f.find("FILE"); at != std::string::npos) f.replace(at, 4, file);
    EXPECT_NE(e.err.find(f), std::string::npos) << "missing: " << f << "\nin: " << e.err;
  }
  if (row.json_out) {
    EXPECT_TRUE(nlohmann::json::accept(e.out)) << e.out;
  } else if (row.status != 0) {
    EXPECT_EQ(e.out, "");
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, HostilePlugins, ::testing::ValuesIn(rows()),
                         [](const ::testing::TestParamInfo<Row>& i) { return i.param.name; });

}  // namespace
}  // namespace fdh::verify::hostile_plugins
