// The scene job (verify/scene/): the shipped scenes (a stable step; robust keeps the exact frame
// audit and FP/FN at 0), their bad input, the audit failing without the skin, and simulate's
// recorded queries, picture and frames; simulate's JSON, and `fdhcert scenes`.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fdh/cli/cli.hpp"
#include "fdh/cloth/cloth.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_file.hpp"
#include "fdh/scene/scene_report.hpp"
#include "fdh/scene/scene_run.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using cloth::Cloth;
using cloth::Scene;

const std::string kScenes = FDH_SOURCE_DIR "/corpus/scenes/";

// --- Scenes ---

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> s;
  for (const auto& e : fs::directory_iterator(kScenes))
    if (e.path().extension() == ".scene") s.push_back(e.path());
  std::sort(s.begin(), s.end());
  return s;
}

TEST(Scenes, ShipAtLeastTheFourOfThePaperAndAStableStep) {
  const auto scenes = shipped_scenes();
  ASSERT_GE(scenes.size(), 4u);
  for (const auto& p : scenes) {
    const Scene s = read_scene(p.string());
    EXPECT_LE(s.dt, Cloth(s.cloth).stable_dt()) << p << ": a shipped scene must be stable";
  }
}

TEST(Scenes, BadInputNamesTheFileAndLine) {
  const fs::path dir = fresh_temp_dir("bad_scene");
  const auto error_of = [&](const std::string& text) {
    const std::string path = (dir / "bad.scene").string();
    std::ofstream(path) << text;
    try {
      read_scene(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("grid 10\nwobble 3\n").find("bad.scene:2: unknown keyword 'wobble'"),
            std::string::npos);
  EXPECT_NE(error_of("grid 1\n").find("bad.scene:1: grid must be"), std::string::npos);
  EXPECT_NE(error_of("# c\nsphere 0 0 0\n").find("bad.scene:2: 'sphere' takes 4 to 5"),
            std::string::npos);
  EXPECT_NE(error_of("box 0 0 0 1 -1 1\n").find("bad.scene:1: box"), std::string::npos);
  EXPECT_NE(error_of("dt nan\n").find("bad.scene:1: dt: 'nan' is not a finite number"),
            std::string::npos);
  EXPECT_NE(error_of("dt 1\ndt 2\n").find("bad.scene:2: 'dt' given twice"), std::string::npos);
  // Through the CLI: exit status 2 and the same message.
  std::ostringstream out, err;
  EXPECT_EQ(run_cli({"simulate", (dir / "bad.scene").string()}, out, err), 2);
  EXPECT_NE(err.str().find("bad.scene:2"), std::string::npos);
}

// With robust, no cloth triangle of any shipped scene meets an obstacle's (nor, with the
// self-collision pass, another cloth triangle) in any checked frame, and the narrow phase agrees
// with the exact test on every query. Each scene runs at most 2e6 particle-frames: every 25x25
// scene whole, but only the first 50 frames of the 200x200 fold (its whole run takes minutes;
// `fdhcert scenes`, in ./run verify, audits it).
TEST(Scenes, RobustKeepsTheAuditAtZeroOnEveryShippedScene) {
  for (const auto& p : shipped_scenes()) {
    const Scene s = read_scene(p.string());
    SceneRunOptions opt;
    opt.narrow = "robust";
    opt.frames = bounded_frames(s, s.frames, 2000000);
    const bool whole = opt.frames == s.frames;
    const SceneRun r = run_scene(s, opt);
    EXPECT_FALSE(r.dt_reduced) << p;
    EXPECT_EQ(r.audit.obstacle_intersections, 0) << p;
    EXPECT_EQ(r.fp, 0) << p;
    EXPECT_EQ(r.fn, 0) << p;
    if (s.self_collision) {
      EXPECT_TRUE(r.self_audited) << p;
      EXPECT_EQ(r.audit.self_intersections, 0) << p;
      if (whole) {
        EXPECT_GT(r.self_hits, 0) << p << ": the cloth never met itself";
      }
    }
    if (!s.obstacles.empty() && whole) {
      EXPECT_GT(r.collisions, 0) << p << ": the cloth never arrived";
    }
  }
}

// Without the skin, a point-only test lets cloth edges cut the table's corners: the audit can
// fail, and does.
TEST(Scenes, WithoutTheSkinEdgesCutTheTableCorners) {
  Scene s = read_scene(kScenes + "table.scene");
  s.thickness = 0;
  const SceneRun r = run_scene(s, {});
  EXPECT_GT(r.audit.obstacle_intersections, 0);
}

TEST(Simulate, RecordsQueriesThatClassifyReplays) {
  const fs::path dir = fresh_temp_dir("simulate");
  const std::string rec = (dir / "run.vf").string(), png = (dir / "last.png").string();
  std::ostringstream out, err;
  ASSERT_EQ(run_cli({"simulate", kScenes + "table.scene", "--grid", "10", "--frames", "600",
                     "--record", rec, "--png", png, "--obj", (dir / "obj").string(), "--json"},
                    out, err),
            0)
      << err.str();
  for (const char* key : {"\"springs\"", "\"refit\"", "\"traversal\"", "\"narrow\"", "\"response\"",
                          "\"candidates\"", "\"crossing\": 0"})
    EXPECT_NE(out.str().find(key), std::string::npos) << key << " in " << out.str();
  EXPECT_TRUE(fs::exists(dir / "obj" / "frame_00600.obj"));
  EXPECT_GT(fs::file_size(png), 1000u);
  const auto queries = read_query_file(rec);
  ASSERT_FALSE(queries.empty());
  std::ostringstream cout_, cerr_;
  EXPECT_EQ(run_cli({"classify", rec, "--methods", "exact,robust", "--check"}, cout_, cerr_), 0)
      << cerr_.str();
}

TEST(SceneReport, JsonIsSimulatesWithNullsForWhatWasNotCounted) {
  cloth::Scene scene;
  scene.name = "s";
  SceneRunOptions opt;
  opt.check = false;
  SceneRun run;
  run.frames = 2;
  run.time.springs = 0.001;
  const auto j = scene_run_json(scene, opt, run);
  EXPECT_EQ(j["scene"], "s");
  EXPECT_EQ(j["narrow"], opt.narrow);
  EXPECT_TRUE(j["fp"].is_null());
  EXPECT_TRUE(j["crossing"].is_null());
  EXPECT_TRUE(j["self_crossing"].is_null());
  EXPECT_DOUBLE_EQ(j["ms_per_frame"]["springs"].get<double>(), 0.5);
  opt.check = true;
  EXPECT_EQ(scene_run_json(scene, opt, run)["crossing"], 0);
  EXPECT_FALSE(scene_run_json(scene, opt, run).contains("inside"));
}

// The table scene cut to a few frames, alone in a folder.
std::filesystem::path short_scene_folder() {
  const std::filesystem::path dir = fresh_temp_dir("scenes_in");
  std::ifstream in(FDH_SOURCE_DIR "/corpus/scenes/table.scene");
  std::ofstream out(dir / "table.scene");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("frames", 0) != 0) out << line << "\n";
  out << "frames 20\n";
  return dir;
}

TEST(Scenes, EachSceneGetsAPictureAJsonAndALine) {
  const std::filesystem::path in = short_scene_folder(), out = fresh_temp_dir("scenes_out");
  std::ostringstream so, se;
  ASSERT_EQ(run_cli({"scenes", "--scenes", in.string(), "--out", out.string()}, so, se), 0)
      << se.str();
  EXPECT_EQ(so.str().rfind("table ", 0), 0u) << so.str();
  EXPECT_NE(so.str().find("crossing 0 self-crossing -"), std::string::npos) << so.str();
  EXPECT_GT(std::filesystem::file_size(out / "table.png"), 1000u);
  std::ifstream json(out / "table.json");
  const auto j = nlohmann::json::parse(json);
  EXPECT_EQ(j["frames"], 20);
  EXPECT_EQ(j["crossing"], 0);
  std::ostringstream so2, se2;
  EXPECT_EQ(run_cli({"scenes", "--scenes", (in / "none").string()}, so2, se2), 2);
}

}  // namespace
}  // namespace fdh::verify
