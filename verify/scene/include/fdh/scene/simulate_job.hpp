// The `simulate` job: one scene file run frame by frame, checked, with the files asked for
// written as it goes. The CLI's simulate and Python's fdhcert.simulate adapt it.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "fdh/cloth/scene.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/scene/scene_outputs.hpp"
#include "fdh/scene/scene_run.hpp"

namespace fdh::verify {

struct SimulateOptions {
  std::string scene_path;
  SceneOverrides overrides;  // --grid, --thickness, --self
  // run.on_start and run.on_frame, when set, are called after the job's own (outputs, progress).
  SceneRunOptions run;
  SceneOutputFiles files;  // "" for none; scene_path is the job's
  int threads = 0;         // 0: every core
  ProgressSink progress;   // hears the frames ("simulate NAME")
};

struct SimulateResult {
  cloth::Scene scene;
  SceneRunOptions run;
  SceneOutputFiles files;
  SceneRun r;
  std::size_t obstacle_triangles = 0;

  nlohmann::ordered_json to_json() const;  // simulate --json (docs/formats.md)
  std::string text() const;                // what simulate prints without --json
};

// Checks every output path, reads the scene (InputError naming the file and line), runs it and
// writes the outputs (the OBJ frames and the recording as it goes, the picture and the movie at
// the end).
SimulateResult simulate_job(SimulateOptions o);

}  // namespace fdh::verify
