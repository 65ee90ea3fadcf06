// What a scene run leaves behind: its JSON (`simulate --json`), its picture, and the runs of
// every shipped scene into one folder (`fdhcert scenes`, which `./run verify` runs).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fdh/cloth/scene.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/io/movie.hpp"
#include "fdh/mesh.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/scene/scene_run.hpp"

namespace fdh::verify {

// The object `fdhcert simulate --json` prints (docs/formats.md, "simulate output"); fp, fn and
// inside and crossing are null when the run was not checked, self_crossing unless audited.
nlohmann::ordered_json scene_run_json(const cloth::Scene& scene, const SceneRunOptions& opt,
                                      const SceneRun& run);

// The last frame of `run` rendered to a PNG: the cloth and the scene's obstacles.
void write_scene_png(const std::string& path, const cloth::Scene& scene, const SceneRun& run);

// A run as an animated PNG (fdh/io/movie.hpp): the cloth and the obstacles at the first frame
// and every stride-th after it, about `movie_frames` in all, 400×300 at 16 frames per second.
class SceneMovie {
 public:
  SceneMovie(const cloth::Scene& scene, int frames_in_run, int movie_frames = 48);
  void frame(const cloth::Simulation& sim, int frame);  // SceneRunOptions::on_frame's
  void write(const std::string& path) const;            // whole; throws without a frame

 private:
  TriMesh obstacles_;
  int stride_;
  Movie movie_;
};

// The *.scene files of a folder, sorted by name. Throws InputError when it is not a folder.
std::vector<std::string> scene_files(const std::string& dir);

// One scene of a folder, run as `fdhcert simulate SCENE --png` runs it.
struct SceneFolderRun {
  std::string file;  // the .scene file
  cloth::Scene scene;
  SceneRunOptions options;
  SceneRun run;
  std::string png, json, movie;  // the files written (movie: "" unless asked for)
};

// What run_scene_folder does beyond the runs: movies, and calls after each frame and scene.
struct SceneFolderOptions {
  bool movies = false;                              // also OUT/<name>-movie.png (SceneMovie)
  ProgressSink progress;                            // hears each scene's frames ("scenes: NAME")
  std::function<void(const SceneFolderRun&)> done;  // after each scene
};

// Every *.scene in `scene_dir` (sorted by name), run with simulate's defaults; writes
// OUT/<name>.png and OUT/<name>.json (the JSON of simulate --json) for each, published whole
// when the last scene is done (fdh/os/output_folder.hpp: all of them or, on failure, OUT as it
// was; OUT's other files are kept). Throws InputError for a bad scene, std::runtime_error for I/O
// failures.
std::vector<SceneFolderRun> run_scene_folder(const std::string& scene_dir,
                                             const std::string& out_dir,
                                             const SceneFolderOptions& opt = {});

// One line for people: the scene, its grid and frames, ms per frame, FP and FN, the exact
// frame audit (inside, crossing, self-crossing).
std::string scene_summary_line(const SceneFolderRun& r);

}  // namespace fdh::verify
