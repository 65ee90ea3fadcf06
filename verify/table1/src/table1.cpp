#include "fdh/table1/table1.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iterator>

#include "fdh/io/charts.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/output_folder.hpp"
#include "fdh/scene/scene_report.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using Out = std::back_insert_iterator<fmt::memory_buffer>;

struct Row {
  const char* method;
  int k;
};
// The paper's "traditional method", the paper's own test as its figures read it, and robust.
constexpr Row kRows[] = {{"linear-system", 18}, {"paper-intended", 18}, {"robust", 6},
                         {"robust", 14},        {"robust", 18},         {"robust", 26}};
constexpr const char* kTraditional = "linear-system";
constexpr const char* kOwn = "paper-intended";

// The paper's numbers, rounded as printed; ours to six significant digits.
std::string grid_name(int g) {
  return fmt::format("{}x{}", g, g);
}

void speed_block(Out to, const Table1& t) {
  fmt::format_to(to,
                 "Table 1 on {}, {} frames per run (ms per frame; paper: Pentium IV 2.8 GHz)\n\n",
                 t.scene, t.frames);
  fmt::format_to(to, "{:<22}{:<4}", "method", "k");
  for (const int g : Table1Paper::grids) fmt::format_to(to, "{:>10}", grid_name(g));
  fmt::format_to(to, "\n{:<26}", "paper: traditional");
  for (const double v : Table1Paper::traditional) fmt::format_to(to, "{:>10.2f}", v);
  fmt::format_to(to, "\n{:<26}", "paper: this paper");
  for (const double v : Table1Paper::own) fmt::format_to(to, "{:>10.2f}", v);
  fmt::format_to(to, "\n");
  for (std::size_t i = 0; i < t.cells.size(); i += Table1Paper::grids.size()) {
    fmt::format_to(to, "{:<22}{:<4}", t.cells[i].method, t.cells[i].k);
    for (std::size_t g = 0; g < Table1Paper::grids.size() && i + g < t.cells.size(); ++g)
      fmt::format_to(to, "{:>10.4f}", t.cells[i + g].run.ms_per_frame());
    fmt::format_to(to, "\n");
  }
}

void accuracy_block(Out to, const Table1& t) {
  fmt::format_to(to,
                 "\nAccuracy of the same runs (FP/FN: narrow-phase queries against the exact "
                 "test;\ninside: cloth particles strictly inside an obstacle; crossing: cloth "
                 "triangles meeting an obstacle triangle; the exact frame audit, summed over "
                 "the frames)\n\n");
  fmt::format_to(to, "{:<16}{:<4}{:<7}{:>9}{:>8}{:>10}{:>7}{:>7}{:>8}{:>10}{:>19}\n", "method", "k",
                 "grid", "ms/frame", "paper", "queries", "FP", "FN", "inside", "crossing",
                 "collision/springs");
  for (const Table1Cell& c : t.cells) {
    const double paper = c.paper_ms();
    const SceneRun& r = c.run;
    fmt::format_to(to, "{:<16}{:<4}{:<7}{:>9.4f}{:>8}{:>10}{:>7}{:>7}{:>8}{:>10}{:>19}\n", c.method,
                   c.k, grid_name(c.grid), r.ms_per_frame(),
                   paper < 0 ? std::string("-") : fmt::format("{:.2f}", paper), r.candidates, r.fp,
                   r.fn, r.audit.inside, r.audit.obstacle_intersections,
                   r.time.springs > 0  // a ratio only where it is finite
                       ? fmt::format("{:.2f}", r.time.collision() / r.time.springs)
                       : std::string("-"));
  }
}

nlohmann::ordered_json cell_json(const Table1Cell& c) {
  const SceneRun& r = c.run;
  const double frames = std::max(1, r.frames);
  return {{"method", c.method},
          {"k", c.k},
          {"grid", c.grid},
          {"ms_per_frame", six_digits(r.ms_per_frame())},
          {"fp", r.fp},
          {"fn", r.fn},
          {"inside", r.audit.inside},
          {"crossing", r.audit.obstacle_intersections},
          {"queries", r.candidates},
          {"collision_ms", six_digits(1e3 * r.time.collision() / frames)},
          {"springs_ms", six_digits(1e3 * r.time.springs / frames)},
          {"dt", six_digits(r.dt)}};
}

std::string chart_commands(const std::string& data) {
  std::vector<std::string> series;
  for (const Row& r : kRows) series.push_back(fmt::format("{} k={}", r.method, r.k));
  series.insert(series.end(), {"paper: traditional", "paper: this paper"});
  std::vector<std::string> plots;
  for (const std::string& s : series)
    plots.push_back(fmt::format(
        "{} skip 1 using (strcol(1) eq {} ? $4 : NaN):5 with linespoints "
        "lw 2 pt 7 title {}",
        plots.empty() ? gnuplot_quote(data) : "''", gnuplot_quote(s), gnuplot_quote(s)));
  return fmt::format(
      "set title \"Table 1: ms per frame, cloth on a table (fdhcert table1)\\nthe paper's rows on "
      "a 2.8 GHz Pentium IV; ours on this machine\"\n"
      "set xlabel 'particles'\nset ylabel 'ms per frame (log)'\nset logscale y\n"
      "set key outside right top\nplot {}\n",
      fmt::join(plots, ", \\\n     "));
}

}  // namespace

double Table1Cell::paper_ms() const {
  const auto g = std::find(Table1Paper::grids.begin(), Table1Paper::grids.end(), grid);
  if (g == Table1Paper::grids.end() || k != 18) return -1;
  const std::size_t i = std::size_t(g - Table1Paper::grids.begin());
  if (method == kTraditional) return Table1Paper::traditional[i];
  if (method == kOwn) return Table1Paper::own[i];
  return -1;
}

Table1 measure_table1(const cloth::Scene& scene, const std::string& scene_path, int frames,
                      const ProgressSink& progress) {
  Table1 t;
  long done = 0;
  t.scene = scene_path;
  for (const Row& row : kRows)
    for (const int g : Table1Paper::grids) {
      Table1Cell cell{row.method, row.k, g, {}};
      report(progress, {"table1", done++, 0, "runs",
                        fmt::format("now {} k={} {}x{}", cell.method, cell.k, g, g)});
      cloth::Scene s = scene;
      s.cloth.grid = g;
      SceneRunOptions opt;
      opt.narrow = row.method;
      opt.k = row.k;
      opt.frames = frames;
      cell.run = run_scene(s, opt);
      t.cells.push_back(std::move(cell));
    }
  t.frames = t.cells.front().run.frames;
  return t;
}

std::string table1_text(const Table1& t) {
  fmt::memory_buffer out;
  speed_block(std::back_inserter(out), t);
  accuracy_block(std::back_inserter(out), t);
  return fmt::to_string(out);
}

std::string table1_headline(const Table1& t) {
  int grid = 0;
  long inside = 0, crossing = 0;
  for (const Table1Cell& c : t.cells) {
    grid = std::max(grid, c.grid);
    inside += c.run.audit.inside, crossing += c.run.audit.obstacle_intersections;
  }
  std::vector<std::string> runs;
  for (const Table1Cell& c : t.cells)
    if (c.grid == grid && c.k == 18)
      runs.push_back(fmt::format("{} {:.4f} (FP {}, FN {})", c.method, c.run.ms_per_frame(),
                                 c.run.fp, c.run.fn));
  const auto g = std::find(Table1Paper::grids.begin(), Table1Paper::grids.end(), grid);
  const std::string paper =
      g == Table1Paper::grids.end()
          ? ""
          : fmt::format("; the paper's: {} {}, {} {}", kTraditional,
                        Table1Paper::traditional[std::size_t(g - Table1Paper::grids.begin())], kOwn,
                        Table1Paper::own[std::size_t(g - Table1Paper::grids.begin())]);
  return fmt::format(
      "Table 1 at {}x{}, k = 18, ms per frame{}\n  {}; audit of every run: {} "
      "inside, {} crossing\n",
      grid, grid, paper, fmt::join(runs, ", "), inside, crossing);
}

nlohmann::ordered_json table1_json(const Table1& t) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const Table1Cell& c : t.cells) rows.push_back(cell_json(c));
  nlohmann::ordered_json paper;
  paper["grids"] = Table1Paper::grids;
  paper[kTraditional] = Table1Paper::traditional;
  paper[kOwn] = Table1Paper::own;
  paper["machine"] = "Pentium IV 2.8 GHz, 1 GB";
  return {{"scene", t.scene}, {"frames", t.frames}, {"rows", rows}, {"paper", paper}};
}

std::string table1_csv(const Table1& t) {
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to, "series,k,grid,particles,ms_per_frame,fp,fn,inside,crossing\n");
  for (const Table1Cell& c : t.cells)
    fmt::format_to(to, "{} k={},{},{},{},{:.6g},{},{},{},{}\n", c.method, c.k, c.k, c.grid,
                   c.grid * c.grid, c.run.ms_per_frame(), c.run.fp, c.run.fn, c.run.audit.inside,
                   c.run.audit.obstacle_intersections);
  const auto paper = [&](const char* series, const std::array<double, 4>& ms) {
    for (std::size_t g = 0; g < ms.size(); ++g)
      fmt::format_to(to, "{},0,{},{},{},,,,\n", series, Table1Paper::grids[g],
                     Table1Paper::grids[g] * Table1Paper::grids[g], ms[g]);
  };
  paper("paper: traditional", Table1Paper::traditional);
  paper("paper: this paper", Table1Paper::own);
  return fmt::to_string(out);
}

std::vector<std::string> table1_outputs() {
  return {"table1.md", "data/table1.csv", "table1.png", "table1.svg"};
}

void write_table1(const Table1& t, const std::string& dir) {
  check_output_folder(dir, table1_outputs());
  OutputFolder out(dir, table1_outputs());  // published whole: issue 34
  out.publish([&](const std::string& into) {
    const fs::path d(into);
    fs::create_directories(d / "data");
    write_file_atomically((d / "data" / "table1.csv").string(), table1_csv(t));
    write_file_atomically(
        (d / "table1.md").string(),
        fmt::format("# Table 1, measured\n\nWritten by `fdhcert table1 --out {}`.\n\n"
                    "![ms per frame against particles](table1.svg)\n\n```\n{}```\n",
                    dir, table1_text(t)));
    draw_chart({(d / "table1").string(), 900, 600, chart_commands("data/table1.csv")});
  });
}

}  // namespace fdh::verify
