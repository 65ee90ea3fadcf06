// What `simulate` writes besides its report: a frame as an OBJ (opens in Blender or ParaView)
// and a frame rendered to a PNG (libpng), both written whole.
#pragma once

#include <array>
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

// A headless render: flat-shaded triangles with a depth buffer, seen from a fixed direction
// (front, right and above) at a distance that fits every mesh in view.
void write_png(const std::string& path, const std::vector<SceneMesh>& meshes, int width = 640,
               int height = 480);

}  // namespace fdh::verify
