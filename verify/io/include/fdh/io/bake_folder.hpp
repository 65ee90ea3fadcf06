// A folder of mesh frames as simulators bake them, passed whole to `fdhcert audit`: numbered
// frames (Blender's cloth_00001.obj, cloth_00002.obj, ...) beside un-numbered static files (its
// obstacle_sphere.obj). The numbered stem is the cloth's sequence, the others fixed obstacles.
#pragma once

#include <string>
#include <vector>

namespace fdh::verify {

// A mesh file by its extension (any case): .obj or .ply.
bool is_mesh_file(const std::string& path);

struct BakeFolder {
  std::vector<std::string> frames;     // in natural order
  std::vector<std::string> obstacles;  // un-numbered files beside numbered frames, natural order
  std::string stem;  // the frames' name before their number and extension ("" if not numbered)
  std::string ext;   // the frames' extension as written (".obj"), "" if not numbered

  // "DIR: the frames are cloth_*.obj (60 files); fixed obstacles: obstacle_sphere.obj", or ""
  // when every file is a frame.
  std::string roles(const std::string& folder) const;
};

// The folder's mesh files. A file whose name (before the extension) ends in digits is numbered,
// its stem what comes before them. With numbered files of one stem and extension, those are the
// frames and every other mesh file a fixed obstacle; with no numbered file, every mesh file is a
// frame, in natural order (frame_2 before frame_10). Throws InputError for a folder that cannot
// be listed, holds no mesh file, or numbered files of more than one stem (naming them).
BakeFolder read_bake_folder(const std::string& folder);

}  // namespace fdh::verify
