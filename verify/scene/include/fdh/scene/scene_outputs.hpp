// What `fdhcert simulate` writes besides its report: the OBJ frames (for `fdhcert audit`,
// Blender or ParaView), every narrow-phase query recorded as a native file, the last frame's
// picture and the run's movie (as `fdhcert scenes` draws them), and the text it prints.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "fdh/cloth/simulation.hpp"
#include "fdh/mesh.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/scene/scene_report.hpp"
#include "fdh/scene/scene_run.hpp"

namespace fdh::verify {

// The files asked for; "" for none.
struct SceneOutputFiles {
  std::string scene_path;  // named in the recording's first line
  std::string obj_dir, png, movie, record;
  int movie_frames = 48;  // about how many frames the movie shows
  // Every output checked before the scene is read or run: one bad path writes nothing.
  void check() const;
};

class SceneOutputs {
 public:
  // `frames`: the run's, for spreading the movie's frames over it. Creates obj_dir.
  SceneOutputs(const SceneOutputFiles& files, const cloth::Scene& scene, int frames);
  const TriMesh& obstacles() const { return obstacles_; }

  void start(const cloth::Simulation& sim) const;  // frame 0, the initial state: an OBJ only
  void frame(const cloth::Simulation& sim, int frame);
  void finish(const cloth::Scene& scene, const SceneRun& r);  // the recording, picture, movie

 private:
  void obj(const cloth::Simulation& sim, int frame) const;

  SceneOutputFiles files_;
  TriMesh obstacles_;
  std::unique_ptr<AtomicFile> recording_;
  std::optional<SceneMovie> movie_;
};

// What `fdhcert simulate` prints of a run: the scene, the step and the time per frame in its
// five parts, then the counts, the checks (when run) and the files written.
struct SimulateText {
  const SceneOutputFiles& files;  // scene_path: the scene as named on the command line
  const SceneRunOptions& run;
  std::size_t obstacle_triangles = 0;
};
std::string simulate_text(const SimulateText& o, const cloth::Scene& scene, const SceneRun& r);

}  // namespace fdh::verify
