// The paper's Table 1 (ms per frame of the cloth on the table at four grid sizes) measured on
// this machine, with the accuracy of each run beside its speed: `fdhcert table1`.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fdh/cloth/scene.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/scene/scene_run.hpp"

namespace fdh::verify {

// Han & Jia 2013, Table 1, on a 2.8 GHz Pentium IV: ms per frame at each grid size.
struct Table1Paper {
  static constexpr std::array<int, 4> grids = {15, 25, 30, 50};
  static constexpr std::array<double, 4> traditional = {12.17, 16.02, 17.43, 22.86};
  static constexpr std::array<double, 4> own = {8.11, 10.68, 12.78, 15.27};
};

// One run: a narrow phase, a k and a grid size.
struct Table1Cell {
  std::string method;
  int k = 0, grid = 0;
  SceneRun run;
  double paper_ms() const;  // the paper's number for this method and grid, or -1
};

struct Table1 {
  std::string scene;              // the scene file
  int frames = 0;                 // frames per run
  std::vector<Table1Cell> cells;  // row by row (method and k), each at every grid size
};

// Runs `scene` at every grid size of the paper with linear-system and paper-intended at
// k = 18 and robust at k = 6, 14, 18, 26; frames < 0 takes the scene's. `progress` hears each
// run as it starts.
Table1 measure_table1(const cloth::Scene& scene, const std::string& scene_path, int frames,
                      const ProgressSink& progress = {});

// The text `fdhcert table1` prints: ms per frame beside the paper's, then each run's accuracy.
std::string table1_text(const Table1& t);

// Two lines: the largest grid's ms per frame of the k = 18 rows (the paper's two and robust)
// beside the paper's, with their FP and FN; the exact audit summed over every run
// (`fdhcert table1 --summary`, `./run verify`).
std::string table1_headline(const Table1& t);

// {"scene", "frames", "rows": [...], "paper": {...}} (docs/formats.md, "table1 output").
nlohmann::ordered_json table1_json(const Table1& t);

// series,k,grid,particles,ms_per_frame,fp,fn,inside,crossing; the paper's rows included.
std::string table1_csv(const Table1& t);

// DIR/table1.md, DIR/data/table1.csv and the chart DIR/table1.png and .svg, published whole
// (fdh/os/output_folder.hpp: all four or, on failure, DIR as it was; the rest of DIR is kept).
// Throws std::runtime_error when a file cannot be written or gnuplot fails.
void write_table1(const Table1& t, const std::string& dir);

// The files write_table1 writes, relative to its folder: for check_output_dir before the run.
std::vector<std::string> table1_outputs();

}  // namespace fdh::verify
