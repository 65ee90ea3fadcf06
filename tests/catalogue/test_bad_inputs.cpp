// The catalogue of bad inputs (issue 14, docs/limits.md): one row per class, each run through
// the command line in-process (fdh::verify::run_cli) with its expected exit status and a
// fragment of its one message. Every row with status 2 must print nothing on standard output,
// give one short line on standard error (no raw control byte, at most a few hundred bytes even
// when the input is megabytes) and leave its --per-query output unwritten.
//
// Small inputs are in tests/data/bad/; big ones are made at test time in a temporary folder.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fdh/cli/cli.hpp"
#include "fdh/cloth/simulation.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_file.hpp"
#include "temp_dir.hpp"
#include "test_data.hpp"

namespace fdh::verify::bad_inputs_catalogue {

namespace fs = std::filesystem;

const std::string kBad = kData + "bad/";
const std::string kGoodLine =
    "vf q 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  1\n";

// One class of bad input: what to run (made in `dir`), the exit status and a fragment of the
// message (of standard error for status 2, of standard output for status 0).
struct Row {
  const char* name;
  std::function<std::vector<std::string>(const fs::path& dir)> args;
  int status;
  std::string fragment;
  std::vector<std::pair<std::string, std::string>> env = {};
};

// The row's name, not its bytes, in GoogleTest's messages.
void PrintTo(const Row& row, std::ostream* os) {
  *os << row.name;
}

std::string write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// Sets environment variables for one row and restores them after.
class EnvGuard {
 public:
  explicit EnvGuard(const std::vector<std::pair<std::string, std::string>>& vars) {
    for (const auto& [k, v] : vars) {
      const char* old = std::getenv(k.c_str());
      saved_.push_back({k, old ? std::optional<std::string>(old) : std::nullopt});
      ::setenv(k.c_str(), v.c_str(), 1);
    }
  }
  ~EnvGuard() {
    for (const auto& [k, v] : saved_)
      v ? ::setenv(k.c_str(), v->c_str(), 1) : ::unsetenv(k.c_str());
  }

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

using Args = std::vector<std::string>;

// Mesh frames and point caches for `audit`'s rows: a square of two triangles, and a file's bytes
// (the binary ones built from little-endian words).
const char* const kSquareObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
const std::string kPlyHeader =  // 115 bytes
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n";

std::string words32(std::initializer_list<std::uint32_t> ws, bool big = false) {
  std::string s;
  for (const std::uint32_t w : ws)
    for (int i = 0; i < 4; ++i) s += char((w >> (8 * (big ? 3 - i : i))) & 0xff);
  return s;
}

Args audit_args(const fs::path& d, const std::string& name, const std::string& bytes,
                bool with_mesh) {
  Args a = {"audit"};
  if (with_mesh) a.push_back(write_text(d / "mesh.obj", kSquareObj));
  a.push_back(write_text(d / name, bytes));
  if (!with_mesh) a.push_back(write_text(d / "other.obj", kSquareObj));
  a.insert(a.end(), {"--out", (d / "out.csv").string()});
  return a;
}

// The catalogue itself: one row per class of bad input. A table, so longer than a function
// should be; each row is read alone.
const std::vector<Row>& rows() {
  static const std::vector<Row> r = {
      // Files that are not there, or not files.
      {"MissingFile",
       [](const fs::path& d) {
         return Args{"classify", (d / "none.vf").string()};
       },
       2, "none.vf: cannot open file"},
      {"FolderAsInput",
       [](const fs::path& d) {
         return Args{"classify", kBad + "good.vf", d.string(), "--per-query",
                     (d / "out.csv").string()};
       },
       2, ": is a folder, not a file"},
      {"FolderAsScene",
       [](const fs::path& d) {
         return Args{"simulate", d.string()};
       },
       2, ": is a folder, not a file"},
      {"DevZeroAsQueries",
       [](const fs::path&) {
         return Args{"classify", "/dev/zero"};
       },
       2,
       "/dev/zero:1: the line is longer than 65536 bytes; the bound is 65536 bytes; set "
       "FDH_MAX_LINE_BYTES"},
      {"DevZeroAsScene",
       [](const fs::path&) {
         return Args{"simulate", "/dev/zero"};
       },
       2, "/dev/zero:1: the line is longer than 65536 bytes"},
      {"DevNullHasNoQuery",
       [](const fs::path&) {
         return Args{"classify", "/dev/null"};
       },
       2, "/dev/null: no query to classify"},
      // Bad text, quoted short and safe.
      {"NotANumber",
       [](const fs::path& d) {
         std::string line = kGoodLine;
         line.replace(line.find("0.25"), 4, "zero");
         return Args{"classify", write_text(d / "zero.vf", line)};
       },
       2, "zero.vf:1: number 1: 'zero' is not a number"},
      {"WrongCountOfNumbers",
       [](const fs::path& d) {
         return Args{"classify", write_text(d / "c.vf", "vf q 1 2 3\n")};
       },
       2, "c.vf:1: expected 'vf <id> <24 numbers> [truth]', found 3 fields after the id"},
      // A method name not in the registry: the hint that a plug-in's need --plugin.
      {"UnknownMethodHintsAtPlugins",
       [](const fs::path& d) {
         return Args{"classify", write_text(d / "m.vf", kGoodLine), "--methods", "fcl-ccd"};
       },
       2, "linear-system); a plug-in's methods need --plugin FILE"},
      // A '#' in an id comments out the rest of the line: the error says so.
      {"HashInsideAnId",
       [](const fs::path& d) {
         return Args{"classify", write_text(d / "h.vf", "vf q#1 1 2 3\n")};
       },
       2,
       "h.vf:1: expected 'vf <id> <24 numbers> [truth]', found 0 fields after the id (the '#' at "
       "column 5 starts a comment: an id cannot hold '#')"},
      {"NulByteInsideANumber",
       [](const fs::path&) {
         return Args{"classify", kBad + "nul_in_number.vf"};
       },
       2, "nul_in_number.vf:1: number 7: '1\\x000' is not a number"},
      {"ControlBytesEscaped",
       [](const fs::path&) {
         return Args{"classify", kBad + "control_kind.vf"};
       },
       2,
       "control_kind.vf:2: a query line starts with 'vf' or 'ee', not "
       "'\\x1b[2J\\x1b]0;owned\\x07'"},
      {"ControlByteInAnId",
       [](const fs::path&) {
         return Args{"classify", kBad + "control_id.vf"};
       },
       2, "control_id.vf:1: the id 'id\\x1b[31m' holds a control byte"},
      {"LongBadNumberCut",  // 60 000 digits and a letter: quoted to 80 bytes and its length
       [](const fs::path& d) {
         std::string line = kGoodLine;
         line.replace(line.find("0.25"), 4, std::string(60000, '1') + "x");
         return Args{"classify", write_text(d / "long.vf", line)};
       },
       2, "long.vf:1: number 1: '" + std::string(80, '1') + "...' (60001 bytes) is not a number"},
      {"TenMegabyteNumberCut",  // with the line bound raised: still 80 bytes quoted
       [](const fs::path& d) {
         std::string line = kGoodLine;
         line.replace(line.find("0.25"), 4, std::string(10000000, '7') + "e");
         return Args{"classify", write_text(d / "huge.vf", line)};
       },
       2,
       "...' (10000001 bytes) is not a number",
       {{"FDH_MAX_LINE_BYTES", "20000000"}}},
      {"UnknownSceneKeywordQuoted",
       [](const fs::path& d) {
         return Args{"simulate", write_text(d / "k.scene", "gr\x1bid 10\n")};
       },
       2, "k.scene:1: unknown keyword 'gr\\x1bid'"},
      {"SceneNameWithControlBytes",
       [](const fs::path&) {
         return Args{"simulate", kBad + "name_control.scene"};
       },
       2, "name_control.scene:1: name 'cloth\\x1b[2J' holds a control byte"},
      // Quietly accepted before.
      {"SpaceInsideCsvInteger",
       [](const fs::path&) {
         return Args{"classify", kBad + "vertex-face/space_in_integer.csv"};
       },
       2, "space_in_integer.csv:3: column 1: '1 0' is not an integer"},
      {"CsvKindNotFromAnywhereInPath",  // edge-edge-notes/ is not edge-edge/
       [](const fs::path&) {
         return Args{"classify", kBad + "edge-edge-notes/good.csv"};
       },
       2,
       "good.csv: cannot tell vertex-face from edge-edge: its folder is not named vertex-face or "
       "edge-edge; pass --kind vf or --kind ee"},
      {"CsvKindFromOption",
       [](const fs::path&) {
         return Args{"classify",  "--kind", "vf",
                     "--methods", "exact",  kBad + "edge-edge-notes/good.csv"};
       },
       0, "1 static vertex-face"},
      {"CsvKindFromExactFolder",
       [](const fs::path&) {
         return Args{"classify", "--methods", "exact", kBad + "vertex-face/good.csv"};
       },
       0, "1 static vertex-face"},
      {"CsvKindFolderAndOptionDisagree",
       [](const fs::path&) {
         return Args{"classify", "--kind", "ee", kBad + "vertex-face/good.csv"};
       },
       2, "good.csv: its folder makes it vf, but --kind ee was given"},
      // Resource bounds: each says the bound and how to raise it.
      {"LineLongerThanTheBound",
       [](const fs::path& d) {
         return Args{"classify", write_text(d / "l.vf", "# " + std::string(70000, 'c') + "\n")};
       },
       2,
       "l.vf:1: the line is longer than 65536 bytes; the bound is 65536 bytes; set "
       "FDH_MAX_LINE_BYTES to raise it (docs/limits.md)"},
      {"LineBoundFromEnvironment",
       [](const fs::path& d) {
         return Args{"classify", write_text(d / "l.vf", kGoodLine + kGoodLine)};
       },
       2,
       "l.vf:1: the line is longer than 50 bytes",
       {{"FDH_MAX_LINE_BYTES", "50"}}},
      {"FileLargerThanTheBound",
       [](const fs::path& d) {
         std::string text;
         for (int i = 0; i < 20; ++i) text += kGoodLine;
         return Args{"classify", write_text(d / "f.vf", text)};
       },
       2,
       "f.vf: the file has 1520 bytes, more than 1000; the bound is 1000 bytes; set "
       "FDH_MAX_FILE_BYTES",
       {{"FDH_MAX_FILE_BYTES", "1000"}}},
      {"StreamLargerThanTheBound",  // a device has no size: the bytes are counted
       [](const fs::path&) {
         return Args{"classify", "/dev/zero"};
       },
       2,
       "/dev/zero:1: the input passes 1000 bytes; the bound is 1000 bytes; set FDH_MAX_FILE_BYTES",
       {{"FDH_MAX_FILE_BYTES", "1000"}}},
      {"MoreQueriesThanTheBound",
       [](const fs::path& d) {
         return Args{"classify", write_text(d / "n.vf", kGoodLine + kGoodLine + kGoodLine)};
       },
       2,
       "n.vf:3: more than 2 queries in one file; the bound is 2 queries; set FDH_MAX_QUERIES",
       {{"FDH_MAX_QUERIES", "2"}}},
      {"CsvMoreQueriesThanTheBound",
       [](const fs::path& d) {
         fs::create_directories(d / "vertex-face");
         std::ifstream in(kBad + "vertex-face/good.csv");
         const std::string one((std::istreambuf_iterator<char>(in)), {});
         return Args{"classify", write_text(d / "vertex-face" / "two.csv", one + one)};
       },
       2,
       "two.csv:9: more than 1 queries in one file",
       {{"FDH_MAX_QUERIES", "1"}}},
      {"MalformedBoundVariable",
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf"};
       },
       2,
       "FDH_MAX_LINE_BYTES: must be a whole number from 1 to 2^62, not 'lots'",
       {{"FDH_MAX_LINE_BYTES", "lots"}}},
      {"GridAboveTheBound",
       [](const fs::path&) {
         return Args{"simulate", kBad + "grid_4000.scene"};
       },
       2,
       "grid_4000.scene:1: grid must be a whole number in [2, 2000], not '4000'; the bound is "
       "2000 particles per side; set FDH_MAX_GRID"},
      {"TooManyObstacleTriangles",
       [](const fs::path&) {
         return Args{"simulate", kBad + "fine_spheres.scene"};
       },
       2,
       "fine_spheres.scene:13: the obstacles have 1064960 triangles, more than 1000000; the bound "
       "is 1000000 triangles; set FDH_MAX_OBSTACLE_TRIANGLES"},
      // Scene values: the field, the value and the range.
      {"StiffnessOutOfRange",
       [](const fs::path&) {
         return Args{"simulate", kBad + "stiffness_1e308.scene"};
       },
       2, "stiffness_1e308.scene:2: stiffness structural must be in (0, 1e+09] N/m, not '1e308'"},
      {"GravityOutOfRange",
       [](const fs::path&) {
         return Args{"simulate", kBad + "gravity_1e308.scene"};
       },
       2, "gravity_1e308.scene:1: gravity y must be in [-1000, 1000] m/s^2, not '-1e308'"},
      {"StepTooSmall",
       [](const fs::path&) {
         return Args{"simulate", kBad + "dt_tiny.scene"};
       },
       2, "dt_tiny.scene:1: dt must be in [1e-09, 1] s, not '1e-300'"},
      {"SizeTooSmall",
       [](const fs::path&) {
         return Args{"simulate", kBad + "size_tiny.scene"};
       },
       2, "size_tiny.scene:1: size must be in [0.001, 1000] m, not '1e-300'"},
      {"BoxTooThin",
       [](const fs::path&) {
         return Args{"simulate", kBad + "box_thin.scene"};
       },
       2, "box_thin.scene:1: box: every side must be at least 0.0001 m"},
      {"StableStepZeroRefused",
       [](const fs::path&) {
         return Args{"simulate", kBad + "stable_step_zero.scene"};
       },
       2, "stable_step_zero.scene:4: the cloth's stable step is"},
      {"ThicknessOutOfRange",
       [](const fs::path& d) {
         return Args{"simulate", write_text(d / "t.scene", "# skin\nthickness 1e308\n")};
       },
       2, "t.scene:2: thickness must be in [0, 1000] m, not '1e308'"},
      {"AuditEveryZero",
       [](const fs::path& d) {
         return Args{"simulate", write_text(d / "a.scene", "grid 5\naudit_every 0\n")};
       },
       2, "a.scene:2: audit_every must be a whole number in [1, 100000000], not '0'"},
      {"ThreadsOutOfRange",
       [](const fs::path&) {
         return Args{"simulate", FDH_SOURCE_DIR "/corpus/scenes/table.scene", "--threads", "0"};
       },
       2, "--threads: Value 0 not in range 1 to 1024"},
      {"CertifyThreadsOutOfRange",
       [](const fs::path&) {
         return Args{"certify", "--threads", "0"};
       },
       2, "--threads: Value 0 not in range 1 to 1024"},
      {"ReportThreadsOutOfRange",
       [](const fs::path&) {
         return Args{"report", "--threads", "2000"};
       },
       2, "--threads: Value 2000 not in range 1 to 1024"},
      {"WindNotFinite",
       [](const fs::path& d) {
         return Args{"simulate", write_text(d / "w.scene", "wind 0 inf 0\n")};
       },
       2, "w.scene:1: wind: 'inf' is not a finite number"},
      // Mesh frames and point caches (`audit`): a bad header or a size that does not match.
      {"PlyUnknownFormat",
       [](const fs::path& d) {
         return audit_args(d, "f.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", false);
       },
       2, "f.ply:2: unknown format 'binary_middle_endian'"},
      {"PlyNotAPly",
       [](const fs::path& d) { return audit_args(d, "f.ply", "solid cube\n", false); }, 2,
       "f.ply:1: not a PLY file: the first line must be 'ply'"},
      {"PlyEndsEarly",
       [](const fs::path& d) {
         return audit_args(d, "f.ply", kPlyHeader + std::string(24 + 3, '\0'), false);
       },
       2, "f.ply: byte 139: the file ends inside vertex 2's x (it has 142 bytes)"},
      {"PlyBytesAfterTheLastElement",
       [](const fs::path& d) {
         return audit_args(d, "f.ply", kPlyHeader + std::string(36 + 3, '\0'), false);
       },
       2, "f.ply: byte 151: 3 bytes after the last element; the header accounts for 151"},
      {"Pc2NotAPc2", [](const fs::path& d) { return audit_args(d, "c.pc2", "POINTCACHE3", true); },
       2, "c.pc2: byte 0: not a PC2 file: it must begin with 'POINTCACHE2' and a zero byte"},
      {"Pc2SizeDoesNotMatch",
       [](const fs::path& d) {
         const std::string head = std::string("POINTCACHE2", 12) + words32({1, 4, 0, 0, 2});
         return audit_args(d, "c.pc2", head + std::string(48, '\0'), true);
       },
       2,
       "c.pc2: byte 32: 2 samples of 4 points need 96 bytes after the 32-byte header, and "
       "the file has 48"},
      {"Pc2PointsAreNotTheMeshVertices",
       [](const fs::path& d) {
         const std::string head = std::string("POINTCACHE2", 12) + words32({1, 3, 0, 0, 1});
         return audit_args(d, "c.pc2", head + std::string(36, '\0'), true);
       },
       2, "c.pc2: byte 16: 3 points, and "},
      {"MddNoFrames",
       [](const fs::path& d) {
         return audit_args(d, "c.mdd", words32({0, 4}, true), true);
       },
       2, "c.mdd: byte 0: 0 frames; a cache needs at least 1"},
      {"MddSizeDoesNotMatch",
       [](const fs::path& d) {
         return audit_args(d, "c.mdd", words32({1, 4, 0}, true) + std::string(47, '\0'), true);
       },
       2,
       "c.mdd: byte 12: 1 frames of 4 points need 48 bytes after the 12-byte header, and the "
       "file has 47"},
      {"CacheWithoutMesh",
       [](const fs::path& d) {
         return Args{"audit", write_text(d / "c.pc2", "POINTCACHE2")};
       },
       2, "c.pc2: a point cache is audited with the mesh that gives its faces"},
      {"DampingTimesStep",
       [](const fs::path&) {
         return Args{"simulate", kBad + "damping_dt.scene"};
       },
       2, "damping_dt.scene:2: damping 1000 1/s times dt 0.01 s must be at most 1"},
  };
  return r;
}

class BadInputCatalogue : public ::testing::TestWithParam<Row> {};

TEST_P(BadInputCatalogue, ExitStatusAndMessage) {
  const Row& row = GetParam();
  const fs::path dir = fresh_temp_dir(std::string("catalogue_") + row.name);
  const Args args = row.args(dir);
  std::ostringstream out, err;
  int status;
  {
    EnvGuard env(row.env);
    status = run_cli(args, out, err);
  }
  EXPECT_EQ(status, row.status) << err.str();
  const std::string& said = row.status == 2 ? err.str() : out.str();
  EXPECT_NE(said.find(row.fragment), std::string::npos) << said.substr(0, 1000);
  if (row.status != 2) return;
  EXPECT_EQ(out.str(), "") << "bad input printed on standard output";
  const std::string e = err.str();
  EXPECT_LE(e.size(), 400u) << "a long message";
  EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 1) << e;
  for (const char ch : e)
    EXPECT_TRUE(ch == '\n' || (static_cast<unsigned char>(ch) >= 0x20 && ch != 0x7f))
        << "a raw control byte in " << e;
  EXPECT_FALSE(fs::exists(dir / "out.csv")) << "an output written despite bad input";
}

INSTANTIATE_TEST_SUITE_P(Rows, BadInputCatalogue, ::testing::ValuesIn(rows()),
                         [](const auto& info) { return std::string(info.param.name); });

// A FIFO is read as a stream: a writer on the other end, and the query comes through.
TEST(BadInputCatalogueSpecial, FifoIsReadCorrectly) {
  const fs::path dir = fresh_temp_dir("catalogue_fifo");
  const std::string fifo = (dir / "q.vf").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << kGoodLine; });
  std::ostringstream out, err;
  const int status = run_cli({"classify", "--methods", "exact", fifo}, out, err);
  // If the reader never opened the FIFO, open it here so that the writer is not left waiting.
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  writer.join();
  if (fd >= 0) ::close(fd);
  EXPECT_EQ(status, 0) << err.str();
  EXPECT_NE(out.str().find("1 static vertex-face"), std::string::npos) << out.str();
}

// Running out of memory while reading is an error (exit 2) naming the file and line, not an
// abort: fdhcert itself, its address space bounded by the shell.
TEST(BadInputCatalogueSpecial, OutOfMemoryIsAnError) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer needs more address space than the bound leaves";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "AddressSanitizer needs more address space than the bound leaves";
#endif
#endif
  const fs::path dir = fresh_temp_dir("catalogue_oom");
  {
    std::ofstream big(dir / "big.vf");
    for (int i = 0; i < 150000; ++i) big << kGoodLine;
  }
  const std::string cmd = "ulimit -v 50000; exec '" FDHCERT_BIN "' classify --methods exact '" +
                          (dir / "big.vf").string() + "' > '" + (dir / "out.txt").string() +
                          "' 2> '" + (dir / "err.txt").string() + "'";
  const int status = std::system(("sh -c \"" + cmd + "\"").c_str());
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal";
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream err(dir / "err.txt");
  const std::string e((std::istreambuf_iterator<char>(err)), {});
  EXPECT_NE(e.find("big.vf:"), std::string::npos) << e;
  EXPECT_NE(e.find(": out of memory after "), std::string::npos) << e;
  EXPECT_EQ(fs::file_size(dir / "out.txt"), 0u);
}

// A directory among the query files of a folder listing (replay, certify's corpus) stays a
// folder to walk; a FIFO is handed to the reader.
TEST(BadInputCatalogueSpecial, ListQueryFilesRefusesWhatIsNotThere) {
  EXPECT_THROW(list_query_files("/nonexistent/fdh"), InputError);
  EXPECT_EQ(list_query_files("/dev/null"), std::vector<std::string>{"/dev/null"});
}

// The message helper: at most 80 bytes of input, control bytes escaped, the length given.
TEST(BadInputCatalogueSpecial, QuoteIsShortAndSafe) {
  EXPECT_EQ(quote("zero"), "'zero'");
  EXPECT_EQ(quote("a\x1b[0m\n\\"), "'a\\x1b[0m\\x0a\\\\'");
  EXPECT_EQ(quote(std::string(100, 'x')), "'" + std::string(80, 'x') + "...' (100 bytes)");
  EXPECT_EQ(quote("\xff\x7f"), "'\\xff\\x7f'");
}

// A scene changed after reading (the command line's --grid) is checked again.
TEST(BadInputCatalogueSpecial, CheckSceneAfterOverrides) {
  cloth::Scene s = read_scene(FDH_SOURCE_DIR "/corpus/scenes/table.scene");
  EXPECT_NO_THROW(check_scene(s, "table.scene"));
  s.cloth.grid = 4000;
  try {
    check_scene(s, "table.scene");
    FAIL() << "grid 4000 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("table.scene: grid must be a whole number in [2, 2000]"),
              std::string::npos)
        << e.what();
  }
  s.cloth.grid = 25;
  s.thickness = 1e300;
  EXPECT_THROW(check_scene(s, "table.scene"), InputError);
}

// Every shipped scene is within the ranges (and so runs as before).
TEST(BadInputCatalogueSpecial, ShippedScenesAreWithinTheRanges) {
  for (const auto& e : fs::directory_iterator(FDH_SOURCE_DIR "/corpus/scenes"))
    if (e.path().extension() == ".scene") {
      EXPECT_NO_THROW(read_scene(e.path().string())) << e.path();
    }
}

// A run that diverges anyway (here: a step far above the stable one, past the scene checks)
// stops with cloth::Diverged, a std::runtime_error the CLI reports with exit status 2, before
// any inf or nan is printed.
TEST(BadInputCatalogueSpecial, DivergingRunStopsWithAnError) {
  cloth::Scene s;
  s.cloth.grid = 5;
  s.cloth.pins = {{0, 0}};  // springs stretch, and a step of 1 s is far above the stable one
  const PointTriangleTest never = [](const Vec3&, const Vec3&, const Vec3&, const Vec3&,
                                     const Vec3&) { return false; };
  cloth::Simulation sim(s, never, 18, /*dt=*/1.0);
  try {
    for (int f = 0; f < 10000; ++f) sim.step();
    FAIL() << "no divergence";
  } catch (const cloth::Diverged& e) {
    EXPECT_NE(std::string(e.what()).find("the cloth diverged at frame"), std::string::npos);
    const std::runtime_error& as_runtime = e;  // what run_cli catches
    (void)as_runtime;
  }
}

}  // namespace fdh::verify::bad_inputs_catalogue
