// fdhcert table1: the paper's Table 1 (ms per frame of the cloth on the table at four grid
// sizes) measured on this machine, with the accuracy of each run beside its speed.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/io/charts.hpp"
#include "fdh/io/json.hpp"
#include "fdh/io/scene_file.hpp"
#include "fdh/suite/scene_run.hpp"

namespace fdh::verify {
namespace {

const char* const kTable1Help =
    R"(usage: fdhcert table1 [--scene FILE] [--frames F] [--json] [--out DIR]

Han & Jia 2013, Table 1: milliseconds per frame of a cloth falling on a table,
at 15x15, 25x25, 30x30 and 50x50 particles, on a 2.8 GHz Pentium IV:
  traditional (linear system)  12.17  16.02  17.43  22.86
  this paper                    8.11  10.68  12.78  15.27
Runs the same scene here (fdhcert simulate, one step per frame) for each row:
  linear-system   k = 18   the paper's "traditional method"
  paper-intended  k = 18   the paper's own test, as its figures read it
  robust          k = 6, 14, 18, 26 (18 is the default of simulate)
and prints the ms per frame beside the paper's numbers, with each run's
accuracy: FP and FN of its narrow-phase queries against the exact test, and
the exact audit (particles inside, crossing edges, summed over the frames).

options:
  --scene FILE   the scene (default: corpus/scenes/table.scene)
  --frames F     frames per run (default: the scene's)
  --json         print {"scene": .., "frames": F, "rows": [{"method": "robust",
                 "k": 26, "grid": 50, "ms_per_frame": .., "fp": .., "fn": ..,
                 "inside": .., "crossing": ..}, ...], "paper": {"grids": [..],
                 "linear-system": [..], "paper-intended": [..]}}
  --out DIR      also write DIR/table1.md, DIR/data/table1.csv and the chart
                 DIR/table1.png and .svg (ms per frame against particles)
  -h, --help     this text
)";

constexpr int kGrids[4] = {15, 25, 30, 50};
constexpr double kPaperTraditional[4] = {12.17, 16.02, 17.43, 22.86};
constexpr double kPaperOwn[4] = {8.11, 10.68, 12.78, 15.27};

struct Row {
  std::string method;
  int k;
};
const Row kRows[] = {{"linear-system", 18}, {"paper-intended", 18}, {"robust", 6},
                     {"robust", 14},        {"robust", 18},         {"robust", 26}};

struct Cell {
  Row row;
  int grid;
  SceneRun run;
};

std::string num(double v, const char* f = "%.4f") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string pad(const std::string& s, std::size_t w) {
  return s.size() >= w ? s : s + std::string(w - s.size(), ' ');
}
std::string lpad(const std::string& s, std::size_t w) {
  return s.size() >= w ? s : std::string(w - s.size(), ' ') + s;
}

std::string text_table(const std::vector<Cell>& cells, const std::string& scene, int frames) {
  std::ostringstream os;
  os << "Table 1 on " << scene << ", " << frames << " frames per run (ms per frame; paper: "
     << "Pentium IV 2.8 GHz)\n\n";
  os << pad("method", 22) << pad("k", 4);
  for (const int g : kGrids) os << lpad(std::to_string(g) + "x" + std::to_string(g), 10);
  os << "\n";
  os << pad("paper: traditional", 26);
  for (const double v : kPaperTraditional) os << lpad(num(v, "%.2f"), 10);
  os << "\n" << pad("paper: this paper", 26);
  for (const double v : kPaperOwn) os << lpad(num(v, "%.2f"), 10);
  os << "\n";
  for (std::size_t r = 0; r < std::size(kRows); ++r) {
    os << pad(kRows[r].method, 22) << pad(std::to_string(kRows[r].k), 4);
    for (std::size_t g = 0; g < 4; ++g) os << lpad(num(cells[r * 4 + g].run.ms_per_frame()), 10);
    os << "\n";
  }
  os << "\nAccuracy of the same runs (FP/FN: narrow-phase queries against the exact test;\n"
     << "inside/crossing: the exact audit, summed over the frames)\n\n";
  os << pad("method", 16) << pad("k", 4) << pad("grid", 7) << lpad("ms/frame", 9)
     << lpad("paper", 8) << lpad("queries", 10) << lpad("FP", 7) << lpad("FN", 7)
     << lpad("inside", 8) << lpad("crossing", 10) << lpad("collision/springs", 19) << "\n";
  for (const Cell& c : cells) {
    const int gi = int(std::find(std::begin(kGrids), std::end(kGrids), c.grid) - kGrids);
    const double paper = c.row.method == "linear-system"    ? kPaperTraditional[gi]
                         : c.row.method == "paper-intended" ? kPaperOwn[gi]
                                                            : -1;
    os << pad(c.row.method, 16) << pad(std::to_string(c.row.k), 4)
       << pad(std::to_string(c.grid) + "x" + std::to_string(c.grid), 7)
       << lpad(num(c.run.ms_per_frame()), 9) << lpad(paper < 0 ? "-" : num(paper, "%.2f"), 8)
       << lpad(std::to_string(c.run.candidates), 10) << lpad(std::to_string(c.run.fp), 7)
       << lpad(std::to_string(c.run.fn), 7) << lpad(std::to_string(c.run.audit.inside), 8)
       << lpad(std::to_string(c.run.audit.crossing), 10)
       << lpad(num(c.run.time.collision() / c.run.time.springs, "%.2f"), 19) << "\n";
  }
  return os.str();
}

std::string json_of(const std::vector<Cell>& cells, const std::string& scene, int frames) {
  std::ostringstream os;
  os << "{\"scene\": " << json_string(scene) << ", \"frames\": " << frames << ", \"rows\": [";
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& c = cells[i];
    os << (i ? ", " : "") << "{\"method\": " << json_string(c.row.method) << ", \"k\": " << c.row.k
       << ", \"grid\": " << c.grid << ", \"ms_per_frame\": " << num(c.run.ms_per_frame(), "%.6g")
       << ", \"fp\": " << c.run.fp << ", \"fn\": " << c.run.fn
       << ", \"inside\": " << c.run.audit.inside << ", \"crossing\": " << c.run.audit.crossing
       << ", \"queries\": " << c.run.candidates << ", \"collision_ms\": "
       << num(1e3 * c.run.time.collision() / std::max(1, c.run.frames), "%.6g")
       << ", \"springs_ms\": " << num(1e3 * c.run.time.springs / std::max(1, c.run.frames), "%.6g")
       << ", \"dt\": " << num(c.run.dt, "%.6g") << "}";
  }
  os << "], \"paper\": {\"grids\": [15, 25, 30, 50], \"linear-system\": [12.17, 16.02, 17.43, "
        "22.86], \"paper-intended\": [8.11, 10.68, 12.78, 15.27], \"machine\": \"Pentium IV "
        "2.8 GHz, 1 GB\"}}\n";
  return os.str();
}

std::string csv_of(const std::vector<Cell>& cells) {
  std::ostringstream os;
  os << "series,k,grid,particles,ms_per_frame,fp,fn,inside,crossing\n";
  for (const Cell& c : cells)
    os << c.row.method << " k=" << c.row.k << "," << c.row.k << "," << c.grid << ","
       << c.grid * c.grid << "," << num(c.run.ms_per_frame(), "%.6g") << "," << c.run.fp << ","
       << c.run.fn << "," << c.run.audit.inside << "," << c.run.audit.crossing << "\n";
  for (int g = 0; g < 4; ++g)
    os << "paper: traditional,0," << kGrids[g] << "," << kGrids[g] * kGrids[g] << ","
       << kPaperTraditional[g] << ",,,,\n";
  for (int g = 0; g < 4; ++g)
    os << "paper: this paper,0," << kGrids[g] << "," << kGrids[g] * kGrids[g] << "," << kPaperOwn[g]
       << ",,,,\n";
  return os.str();
}

}  // namespace

int table1_command(const Args& args, std::ostream& out, std::ostream& err) {
  std::string scene_path = "corpus/scenes/table.scene", out_dir;
  int frames = -1;
  bool json = false;
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kTable1Help;
      return 0;
    } else if (a.is("--scene")) {
      scene_path = a.value();
    } else if (a.is("--frames")) {
      frames = int(a.integer(1, 100000000));
    } else if (a.is("--json")) {
      json = true;
    } else if (a.is("--out")) {
      out_dir = a.value();
    } else if (a.is_option()) {
      a.unknown("table1");
    } else {
      throw UsageError("table1 takes no positional argument ('" + a.word() + "')");
    }
  }
  const cloth::Scene scene = read_scene(scene_path);
  std::vector<Cell> cells;
  const bool progress = !json && &err == &std::cerr && ::isatty(STDERR_FILENO);
  for (const Row& row : kRows)
    for (const int g : kGrids) {
      cloth::Scene s = scene;
      s.cloth.grid = g;
      SceneRunOptions opt;
      opt.narrow = row.method;
      opt.k = row.k;
      opt.frames = frames;
      if (progress)
        err << "table1: " << row.method << " k=" << row.k << " " << g << "x" << g << "\r"
            << std::flush;
      cells.push_back({row, g, run_scene(s, opt)});
    }
  if (progress) err << std::string(40, ' ') << "\r";
  const int used_frames = cells.front().run.frames;
  const std::string table = text_table(cells, scene_path, used_frames);
  if (!out_dir.empty()) {
    std::filesystem::create_directories(out_dir + "/data");
    write_file_atomically(out_dir + "/data/table1.csv", csv_of(cells));
    write_file_atomically(out_dir + "/table1.md",
                          "# Table 1, measured\n\nWritten by `fdhcert table1 --out " + out_dir +
                              "`.\n\n![ms per frame against particles](table1.svg)\n\n```\n" +
                              table + "```\n");
    draw_table1_chart(out_dir);
  }
  out << (json ? json_of(cells, scene_path, used_frames) : table);
  return 0;
}

}  // namespace fdh::verify
