// A run as an animated PNG (APNG: PNG plus the acTL, fcTL and fdAT chunks of the APNG
// specification, https://wiki.mozilla.org/APNG_Specification). Each frame is rendered and
// encoded by libpng (scene_output.hpp); this file only re-wraps the frames' image data as APNG
// chunks. Browsers and GitHub play it; viewers without APNG show the first frame.
#pragma once

#include <string>
#include <vector>

#include "fdh/io/scene_output.hpp"

namespace fdh::verify {

class Movie {
 public:
  // `fps` frames per second, looping forever. The view is fixed by the first frame's meshes
  // (a margin of `margin` times their framing radius), so that the camera stays still.
  Movie(int width, int height, int fps, double margin = 1.1);

  void add_frame(const std::vector<SceneMesh>& meshes);

  // The APNG bytes of every frame added. Throws std::logic_error without a frame.
  std::string bytes() const;
  // bytes(), written whole.
  void write(const std::string& path) const;

 private:
  int width_, height_, fps_;
  double margin_;
  Framing view_;
  std::string ihdr_;                 // the first frame's header
  std::vector<std::string> frames_;  // each frame's zlib image data (its IDATs joined)
};

}  // namespace fdh::verify
