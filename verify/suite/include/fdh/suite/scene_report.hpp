// What a scene run leaves behind: its JSON (`simulate --json`), its picture, and the runs of
// every shipped scene into one folder (`fdhcert scenes`, which `./run verify` runs).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fdh/cloth/scene.hpp"
#include "fdh/suite/scene_run.hpp"

namespace fdh::verify {

// The object `fdhcert simulate --json` prints (docs/formats.md, "simulate output"); fp, fn,
// inside and crossing are null when the run was not checked, self_crossing unless audited.
nlohmann::ordered_json scene_run_json(const cloth::Scene& scene, const SceneRunOptions& opt,
                                      const SceneRun& run);

// The last frame of `run` rendered to a PNG: the cloth and the scene's obstacles.
void write_scene_png(const std::string& path, const cloth::Scene& scene, const SceneRun& run);

// The *.scene files of a folder, sorted by name. Throws InputError when it is not a folder.
std::vector<std::string> scene_files(const std::string& dir);

// One scene of a folder, run as `fdhcert simulate SCENE --png` runs it.
struct SceneFolderRun {
  std::string file;  // the .scene file
  cloth::Scene scene;
  SceneRunOptions options;
  SceneRun run;
  std::string png, json;  // the files written
};

// Every *.scene in `scene_dir` (sorted by name), run with simulate's defaults; writes
// OUT/<name>.png and OUT/<name>.json (the JSON of simulate --json) for each, and calls `done`
// after each scene. Throws InputError for a bad scene, std::runtime_error for I/O failures.
std::vector<SceneFolderRun> run_scene_folder(
    const std::string& scene_dir, const std::string& out_dir,
    const std::function<void(const SceneFolderRun&)>& done = {});

// One line for people: the scene, its grid and frames, ms per frame, FP and FN, the exact
// audit (inside, crossing, self-crossing).
std::string scene_summary_line(const SceneFolderRun& r);

// j as text (two-space indented, then a newline), the one way every JSON output is written.
// JSON has no NaN or infinity (nlohmann would write null silently): a non-finite number
// anywhere in j throws std::runtime_error naming its place (a JSON pointer) and `what`.
std::string json_text(const nlohmann::ordered_json& j, const std::string& what);

// v to six significant digits: the precision of every time and energy in the JSON outputs.
double six_digits(double v);

}  // namespace fdh::verify
