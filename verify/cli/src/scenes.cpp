// fdhcert scenes: every shipped scene run as `simulate` runs it, a picture and a JSON each.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "fdh/os/atomic_file.hpp"
#include "fdh/os/output_folder.hpp"
#include "fdh/scene/scene_report.hpp"
#include "suite_commands.hpp"

namespace fdh::verify {
namespace {

const char* const kScenesAbout =
    R"(run every scene of a folder: a picture, a JSON and a line each

Runs each *.scene of the folder (in name order) as `fdhcert simulate SCENE
--png OUT/NAME.png --json` would, with the scene's own grid and frames,
robust, k = 18, writes OUT/NAME.png and OUT/NAME.json (the object of
simulate --json, docs/formats.md), and prints one line per scene: its grid,
frames, ms per frame, FP and FN against the exact test, and the exact audit
(inside: cloth particles strictly inside an obstacle; crossing: cloth
triangles meeting an obstacle triangle; self-crossing: cloth triangles
meeting one sharing no particle, - where not audited).
With --movies, also OUT/NAME-movie.png: the run as an animated PNG.
`./run verify` runs it into docs/scenes.
)";

struct ScenesOptions {
  std::string scenes = "corpus/scenes", out_dir = "scenes";
  bool movies = false;
  ProgressWhen progress = ProgressWhen::Auto;
};

int run_scenes(const ScenesOptions& o, const Io& io) {
  check_output_folder(o.out_dir);  // and each scene's outputs, in run_scene_folder, before any run
  ProgressLine progress(io.err, progress_wanted(io, o.progress));
  SceneFolderOptions opt;
  opt.movies = o.movies;
  opt.progress = progress.sink();
  opt.done = [&](const SceneFolderRun& r) {
    progress.clear();
    io.out << scene_summary_line(r) << std::endl;
  };
  const auto runs = run_scene_folder(o.scenes, o.out_dir, opt);
  io.out << "scenes: wrote a picture" << (o.movies ? ", a movie" : "") << " and a JSON for each of "
         << runs.size() << " scenes to " << o.out_dir << "\n";
  return 0;
}

}  // namespace

Command add_scenes(CLI::App& app) {
  auto o = std::make_shared<ScenesOptions>();
  CLI::App* cmd = app.add_subcommand("scenes", kScenesAbout);
  cmd->add_option("--scenes", o->scenes, "the folder of scenes (default: corpus/scenes)")
      ->type_name("DIR");
  cmd->add_option("--out", o->out_dir,
                  "where the pictures and JSON go, created if needed (default:\nscenes)")
      ->type_name("DIR");
  add_quiet_flag(*cmd, o->progress);
  cmd->add_flag("--movies", o->movies,
                "also render each run to OUT/NAME-movie.png, an animated PNG\n"
                "(simulate --movie)");
  return {cmd, [o](const Io& io) { return run_scenes(*o, io); }};
}

}  // namespace fdh::verify
