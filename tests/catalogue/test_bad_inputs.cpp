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
#include <chrono>
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

#include "fdh/certify/certify.hpp"
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

// A frame for `audit`: a cloth triangle far above two obstacle triangles that cross each other.
// Clean, as obstacles may cross; were the obstacles read as cloth, a self-intersection.
const std::string kCrossedObstacles =
    "o cloth\nv 0 0 5\nv 1 0 5\nv 1 1 5\nf 1 2 3\no obstacles\nv -1 0 0\nv 1 0 0\n"
    "v 0 0 1\nv 0 -1 0.5\nv 0 1 0.5\nv 0 0 -0.5\nf 4 5 6\nf 7 8 9\n";
// A cloth square and an obstacle triangle through it: a violation within the frame.
const std::string kPierced =
    "o cloth\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\no obstacles\n"
    "v 0.5 0.2 -1\nv 0.5 0.2 1\nv 0.6 0.9 0\nf 5 6 7\n";
// The options of a `replay --toi` on one stored moving case.
const std::string kMovingCase = FDH_SOURCE_DIR "/corpus/toi/float-cubic/coplanar";

// Two frames for `audit`: `first`, then `second`, in a folder of their own.
std::string two_frames(const fs::path& d, const std::string& first, const std::string& second) {
  fs::create_directories(d / "seq");
  write_text(d / "seq" / "f1.obj", first);
  write_text(d / "seq" / "f2.obj", second);
  return (d / "seq").string();
}

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
      // Issue 34, class 1: a wrong answer from a byte-order mark; other encodings, unknown words.
      {"ObjByteOrderMarkKeepsTheFirstLine",  // `o cloth` was lost: 1 violation, not clean
       [](const fs::path& d) {
         return Args{"audit", write_text(d / "bom.obj", "\xEF\xBB\xBF" + kCrossedObstacles)};
       },
       0, "clean: 1 frame, 0 steps, 0 violations"},
      {"ObjUtf16RefusedByName",  // was "no faces"
       [](const fs::path& d) {
         std::string utf16 = "\xFF\xFE";
         for (const char c : kCrossedObstacles) utf16 += std::string(1, c) + '\0';
         return Args{"audit", write_text(d / "u16.obj", utf16)};
       },
       2, "u16.obj:1: the file is UTF-16; an OBJ file must be UTF-8 or ASCII"},
      {"ObjUnknownStatementRefused",
       [](const fs::path& d) {
         return Args{"audit", write_text(d / "w.obj", "vv 0 0 0\n" + kCrossedObstacles)};
       },
       2, "w.obj:1: unknown statement 'vv': not an OBJ keyword"},
      // Class 3: a plug-in's words are quoted as any input is.
      {"PluginRefusalEscaped",
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf", "--plugin",
                     FDH_TUNABLE_PLUGIN ":answer=\x1b[2J\x07x"};
       },
       2, "refused its settings: 'cannot take answer=\\x1b[2J\\x07x"},
      // Class 4 and 6: NaN passed CLI11's Range (both comparisons false).
      {"WidthNaN",
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf", "--toi", "--width", "nan"};
       },
       2, "--width: 'nan' is not a finite number; give a number in [2^-52, 1]"},
      {"ReplayToleranceNaN",  // exited 0
       [](const fs::path&) {
         return Args{"replay", kMovingCase, "--toi", "--toi-tolerance", "nan"};
       },
       2, "--toi-tolerance: 'nan' is not a finite number; give a number in [0, 1]"},
      {"FuzzWidthNaN",
       [](const fs::path& d) {
         return Args{"fuzz",
                     "--method",
                     "robust",
                     "--family",
                     "random-linear",
                     "--out",
                     (d / "out.csv").string(),
                     "--toi",
                     "--width",
                     "nan"};
       },
       2, "--width: 'nan' is not a finite number"},
      {"BudgetNaN",
       [](const fs::path&) {
         return Args{"certify", "--budget", "nan"};
       },
       2, "--budget: 'nan' is not a finite number; give a number in [0.001, 1e+07]"},
      {"PluginTimeoutNaN",
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf", "--plugin-timeout", "nan"};
       },
       2, "--plugin-timeout: 'nan' is not a finite number"},
      {"RatioLimitNaN",
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf", "--ratio-limit", "nan"};
       },
       2, "--ratio-limit: 'nan' is not a finite number; give a number in [0.001, 1000]"},
      {"MinDistanceNaN",  // "fdhcert: min distance must be ...", no option named
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf", "--min-distance", "nan"};
       },
       2, "--min-distance: takes a finite number >= 0: 'nan' is not a finite number"},
      // Class 9: messages that said something else than what was wrong.
      {"ObjHexFloatAndUnderflowTaken",  // were "not a finite number"
       [](const fs::path& d) {
         std::string text = kCrossedObstacles;
         text.replace(text.find("v 0 0 5"), 7, "v 0x0p+0 1e-400 5");
         return Args{"audit", write_text(d / "hex.obj", text)};
       },
       0, "clean: 1 frame, 0 steps, 0 violations"},
      {"ObjOverflowNamed",
       [](const fs::path& d) {
         return Args{"audit", write_text(d / "o.obj", "v 1e400 0 0\n" + kCrossedObstacles)};
       },
       2, "o.obj:1: coordinate 1: '1e400' is outside the range of a double"},
      {"LinkLoopNamed",  // was "no such file or folder"
       [](const fs::path& d) {
         fs::create_symlink(d / "loop.obj", d / "loop.obj");
         return Args{"audit", (d / "loop.obj").string()};
       },
       2, "loop.obj: cannot be read: Too many levels of symbolic links"},
      {"ReplayLinkLoopNamed",  // was "no such file or folder"
       [](const fs::path& d) {
         fs::create_symlink(d / "loop", d / "loop");
         return Args{"replay", (d / "loop").string()};
       },
       2, "loop: cannot be read: Too many levels of symbolic links"},
      {"CertifyCorpusLinkLoopNamed",  // was the raw "filesystem error: status: ..."
       [](const fs::path& d) {
         fs::create_symlink(d / "loop", d / "loop");
         return Args{"certify",  "--quick",
                     "--corpus", (d / "loop").string(),
                     "--out",    (d / "out.csv").string()};
       },
       2, "loop: cannot be read: Too many levels of symbolic links"},
      {"ScenesLinkLoopNamed",  // was the raw "filesystem error: status: ..."
       [](const fs::path& d) {
         fs::create_symlink(d / "loop", d / "loop");
         return Args{"scenes", "--scenes", (d / "loop").string(), "--out",
                     (d / "out.csv").string()};
       },
       2, "loop: cannot be read: Too many levels of symbolic links"},
      {"WidthRangeWritten",  // was "0.000000 to 1.000000"
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf", "--toi", "--width", "1e-300"};
       },
       2, "--width: Value '1e-300' not in range [2^-52, 1]"},
      {"WidthAsTheHelpWritesIt",
       [](const fs::path&) {
         return Args{"classify", "--methods", "exact", kBad + "good.vf",
                     "--toi",    "--width",   "2^-10"};
       },
       0, "1 static vertex-face"},
      {"WidthWithoutToi",  // was ignored
       [](const fs::path&) {
         return Args{"classify", kBad + "good.vf", "--width", "2^-10"};
       },
       2, "--width requires --toi"},
      {"ReplayWidthWithoutToi",
       [](const fs::path&) {
         return Args{"replay", kMovingCase, "--width", "2^-10"};
       },
       2, "--width requires --toi"},
      {"AuditPlacesByTheJsonRule",  // a Latin-1 name: U+EFE9 in JSON, as docs/formats.md says
       [](const fs::path& d) {
         return Args{"audit", "--json", write_text(d / "caf\xe9.obj", kPierced)};
       },
       1, "caf\xee\xbf\xa9.obj:6"},
      {"VertexMoreNamesTheLine",  // named the file only
       [](const fs::path& d) {
         return Args{"audit", two_frames(d, kCrossedObstacles, kCrossedObstacles + "v 0 0 0\n")};
       },
       2, "f2.obj:15: 10 vertices, and "},
      {"OneFrame",  // "1 frames"
       [](const fs::path& d) {
         return Args{"audit", write_text(d / "one.obj", kCrossedObstacles)};
       },
       0, "clean: 1 frame, 0 steps"},
      {"ClothNamedInAFileWithoutObjects",  // "(objects: '')"
       [](const fs::path& d) {
         return Args{"audit", write_text(d / "n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                     "--cloth", "sheet"};
       },
       2, "n.obj: no object named 'sheet' (the file has no o or g line; without --cloth"},
      {"RotatedFaceIsTheSameFace",  // was "differs"
       [](const fs::path& d) {
         std::string later = kCrossedObstacles;
         later.replace(later.find("f 4 5 6"), 7, "f 5 6 4");
         return Args{"audit", two_frames(d, kCrossedObstacles, later)};
       },
       0, "clean: 2 frames, 1 step, 0 violations"},
      {"ReversedFaceStillDiffers",
       [](const fs::path& d) {
         std::string later = kCrossedObstacles;
         later.replace(later.find("f 4 5 6"), 7, "f 4 6 5");
         return Args{"audit", two_frames(d, kCrossedObstacles, later)};
       },
       2, "f2.obj:13: face 2 differs from "},
      // Class 10: an extra file is read before the work starts (it was read last, after 13 s).
      {"CertifyReadsExtraFilesFirst",
       [](const fs::path& d) {
         return Args{"certify", "--quick", "--out", (d / "cert").string(),
                     write_text(d / "BAD.vf", "vf q 1 2 3\n")};
       },
       2, "BAD.vf:1: expected 'vf <id> <24 numbers> [truth]'"},
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

// Issue 34, class 9: the quads note counts a later frame's quads too (it was printed only when
// the first frame had them), in the singular for one.
TEST(BadInputCatalogueSpecial, QuadsOfALaterFrameAreSaid) {
  const fs::path d = fresh_temp_dir("catalogue_later_quads");
  const std::string tris = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
  const std::string quad = "v 0 0 0.1\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  const std::string seq = two_frames(d, tris, quad);
  std::ostringstream out, err;
  EXPECT_EQ(run_cli({"audit", seq}, out, err), 0) << err.str();
  EXPECT_EQ(err.str(),
            "fdhcert: note: 1 face of more than three vertices was split into triangles (fan)\n");
}

// Class 9: a clean audit --out makes no empty cases/ folder; one with a violation has its cases.
TEST(BadInputCatalogueSpecial, CleanAuditMakesNoCasesFolder) {
  const fs::path d = fresh_temp_dir("catalogue_no_cases");
  std::ostringstream out, err;
  const std::string clean = write_text(d / "c.obj", kCrossedObstacles);
  EXPECT_EQ(run_cli({"audit", clean, "--out", (d / "out").string()}, out, err), 0) << err.str();
  EXPECT_TRUE(fs::exists(d / "out" / "audit.json"));
  EXPECT_FALSE(fs::exists(d / "out" / "cases"));
}

// Class 10: a bad extra file is refused before the work starts: at once, not after the corpus,
// the families and the scenes (13 s with --quick).
TEST(BadInputCatalogueSpecial, CertifyRefusesABadExtraFileAtOnce) {
  const fs::path d = fresh_temp_dir("catalogue_certify_extra");
  const std::string bad = write_text(d / "BAD.vf", "vf q 1 2 3\n");
  std::ostringstream out, err;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run_cli({"certify", "--quick", "--out", (d / "cert").string(), bad}, out, err), 2);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0) << "the extra file was read after the work";
  EXPECT_EQ(out.str(), "");
  EXPECT_FALSE(fs::exists(d / "cert" / "certificate.json"));
}

// Class 10: `scenes` reads every scene before it runs the first: a bad one is refused before any
// output is written (it was found after the scenes before it had run and written theirs).
TEST(BadInputCatalogueSpecial, ScenesReadsEverySceneFirst) {
  const fs::path d = fresh_temp_dir("catalogue_scenes_first");
  fs::create_directories(d / "scenes");
  write_text(d / "scenes" / "a.scene", "name a\ngrid 5\nframes 2\n");
  write_text(d / "scenes" / "b.scene", "grid 5\nframes nine\n");
  std::ostringstream out, err;
  EXPECT_EQ(run_cli({"scenes", "--scenes", (d / "scenes").string(), "--out", (d / "out").string()},
                    out, err),
            2);
  EXPECT_NE(err.str().find("b.scene:2: "), std::string::npos) << err.str();
  EXPECT_FALSE(fs::exists(d / "out")) << "a scene ran before the bad one was read";
}

// Class 3: a plug-in's settings go into certificate.md with their control bytes as \xNN.
TEST(BadInputCatalogueSpecial, CertificateWritesSettingsPrintable) {
  const fs::path d = fresh_temp_dir("catalogue_certificate_settings");
  Certificate c;
  c.options.out_dir = (d / "cert").string();
  fs::create_directories(c.options.out_dir);  // as certify makes it
  c.options.plugins = {{"p\x1b.so",
                        "p",
                        {{"mode",
                          "a\x1b[2J\x07"
                          "b"}},
                        false}};
  write_certificate(c);
  std::ifstream in(d / "cert" / "certificate.md", std::ios::binary);
  const std::string md((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(md.find("`mode=a\\x1b[2J\\x07b`"), std::string::npos) << md;
  EXPECT_NE(md.find("`p\\x1b.so`"), std::string::npos) << md;
  EXPECT_EQ(md.find('\x1b'), std::string::npos);
  EXPECT_EQ(md.find('\x07'), std::string::npos);
}

}  // namespace fdh::verify::bad_inputs_catalogue
