#include "fdh/scene/simulate_job.hpp"

#include <nlohmann/json.hpp>

#include <utility>

#include "fdh/check/thread_limit.hpp"
#include "fdh/scene/scene_report.hpp"

namespace fdh::verify {

SimulateResult simulate_job(SimulateOptions o) {
  o.files.scene_path = o.scene_path;
  o.files.check();  // before the scene is read: one bad path writes nothing
  const ThreadLimit threads(o.threads);
  SimulateResult res;
  res.scene = read_scene_overridden(o.scene_path, o.overrides);
  const cloth::Scene& scene = res.scene;
  const int frames = o.run.frames < 0 ? scene.frames : o.run.frames;
  SceneOutputs outputs(o.files, scene, frames);
  SceneRunOptions run = o.run;
  run.on_start = [&](const cloth::Simulation& sim) {
    outputs.start(sim);
    if (o.run.on_start) o.run.on_start(sim);
  };
  run.on_frame = [&](const cloth::Simulation& sim, int frame) {
    outputs.frame(sim, frame);
    report(o.progress, {"simulate " + scene.name, frame, frames, "frames"});
    if (o.run.on_frame) o.run.on_frame(sim, frame);
  };
  res.r = run_scene(scene, run);
  outputs.finish(scene, res.r);
  res.run = std::move(o.run);
  res.run.on_start = nullptr, res.run.on_frame = nullptr;  // the caller's, gone with the run
  res.files = std::move(o.files);
  res.obstacle_triangles = outputs.obstacles().tris.size();
  return res;
}

nlohmann::ordered_json SimulateResult::to_json() const {
  return scene_run_json(scene, run, r);
}

std::string SimulateResult::text() const {
  return simulate_text({files, run, obstacle_triangles}, scene, r);
}

}  // namespace fdh::verify
