// What `simulate` writes besides its report: a frame as an OBJ (opens in Blender or ParaView)
// and a frame rendered to a PNG (libpng), both written whole.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/vec3.hpp"

namespace fdh::verify {

struct SceneMesh {
  std::string name;
  const std::vector<Vec3>* x;
  const std::vector<Tri>* tris;
  std::array<double, 3> colour;  // RGB in [0,1], for the picture
};

// One OBJ with one object (`o name`) per mesh.
void write_obj(const std::string& path, const std::vector<SceneMesh>& meshes);

// What a picture shows: a sphere around the meshes, seen from a direction (by default front,
// right and above; y is up) at a distance that fits it in view.
struct Framing {
  Vec3 centre;
  double radius = 1;
  Vec3 towards_eye{0.55, 0.45, 1.0};  // from the centre towards the eye; not along y
};
Framing frame_view(const std::vector<SceneMesh>& meshes);

// RGB pixels, row by row from the top.
struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

// A headless render: flat-shaded triangles with a depth buffer, framed by `view` (default: the
// meshes' own, frame_view).
Picture render(const std::vector<SceneMesh>& meshes, int width, int height,
               std::optional<Framing> view = std::nullopt);

// The picture as PNG bytes (libpng). Throws std::runtime_error if libpng fails.
std::string encode_png(const Picture& pic);

// render, encode_png, written whole.
void write_png(const std::string& path, const std::vector<SceneMesh>& meshes, int width = 640,
               int height = 480);

}  // namespace fdh::verify
