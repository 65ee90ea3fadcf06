#include "fdh/scene/scene_outputs.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>

#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_output.hpp"

namespace fdh::verify {
namespace {

const std::array<double, 3> kClothColour = {0.85, 0.25, 0.2}, kObstacleColour = {0.7, 0.7, 0.65};

}  // namespace

void SceneOutputFiles::check() const {
  if (!png.empty()) check_output_path(png);
  if (!movie.empty()) check_output_path(movie);
  if (!record.empty()) check_output_path(record);
  if (!obj_dir.empty()) check_output_dir(obj_dir);
}

SceneOutputs::SceneOutputs(const SceneOutputFiles& files, const cloth::Scene& scene, int frames)
    : files_(files), obstacles_(obstacles_of(scene)) {
  if (!files_.obj_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(files_.obj_dir, ec);
    if (ec) throw std::runtime_error(files_.obj_dir + ": cannot create folder: " + ec.message());
  }
  if (!files_.movie.empty()) movie_.emplace(scene, frames, files_.movie_frames);
  if (!files_.record.empty()) {
    recording_ = std::make_unique<AtomicFile>(files_.record);
    recording_->stream() << "# fdhcert simulate " << files_.scene_path
                         << ": every narrow-phase query\n";
  }
}

void SceneOutputs::obj(const cloth::Simulation& sim, int frame) const {
  if (files_.obj_dir.empty()) return;
  write_obj(files_.obj_dir + fmt::format("/frame_{:05d}.obj", frame),
            {{"cloth", &sim.cloth().x(), &sim.cloth().triangles(), kClothColour},
             {"obstacles", &obstacles_.x, &obstacles_.tris, kObstacleColour}});
}

void SceneOutputs::start(const cloth::Simulation& sim) const {
  obj(sim, 0);
}

void SceneOutputs::frame(const cloth::Simulation& sim, int frame) {
  if (movie_) movie_->frame(sim, frame);
  obj(sim, frame);
  if (!recording_) return;
  for (const auto& q : sim.queries()) {
    QueryRecord r;
    r.query = sim.query(q);
    r.id = fmt::format("f{}p{}t{}", frame, q.particle, q.triangle);
    write_native(recording_->stream(), r);
  }
}

void SceneOutputs::finish(const cloth::Scene& scene, const SceneRun& r) {
  if (recording_) recording_->commit();
  if (!files_.png.empty()) write_scene_png(files_.png, scene, r);
  if (movie_ && r.frames > 0) movie_->write(files_.movie);
}

}  // namespace fdh::verify
