// A sequence of mesh frames on disk, for `fdhcert audit`: one OBJ or PLY per frame (as `simulate
// --obj`, Blender or any simulator writes them), or a mesh and a point cache of its vertices'
// positions (PC2, MDD: fdh/io/point_cache.hpp); a cloth and the obstacles that move with it, plus
// obstacle files of their own. Every frame must have frame 0's faces. Frames are read one at a
// time, so a long sequence streams.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/io/obj_file.hpp"
#include "fdh/vec3.hpp"

namespace fdh::verify {

// The frame files of `args`, in order: a file is kept as it is; a folder gives its numbered
// `*.obj` or `*.ply` files (any case of the extension) in natural order (fdh/io/bake_folder.hpp).
// A folder's un-numbered files beside numbered ones are fixed obstacles: added to `fixed` (with
// their folder's roles line to `notes`), or an InputError where `fixed` is null. Throws
// InputError for a path that does not exist, or a folder without an OBJ or PLY file.
std::vector<std::string> frame_files(const std::vector<std::string>& args,
                                     std::vector<std::string>* fixed = nullptr,
                                     std::vector<std::string>* notes = nullptr);

// A mesh file as the reader of its extension reads it: PLY (fdh/io/ply_file.hpp), else OBJ.
ObjFile read_mesh(const std::string& path);

// Natural order: runs of digits compare as numbers, so frame_2 comes before frame_10; names
// equal as numbers (frame_02, frame_2) in byte order, so that the order is total.
bool natural_less(const std::string& a, const std::string& b);

// The faces, fixed for the whole sequence: the cloth's and the obstacles', each indexing its own
// vertices (0-based, in the order of the files).
struct SequenceTopology {
  int cloth_vertices = 0;
  std::vector<Tri> cloth;
  int obstacle_vertices = 0;
  std::vector<Tri> obstacle;
};

// Where primitives stand in the files: the file and the line of each `v` or `f`, by index.
// A binary file's places are byte offsets: "FILE:byte N".
class Places {
 public:
  void add(std::string file, std::shared_ptr<const std::vector<int>> lines, bool bytes = false);
  // "FILE:LINE" (or "FILE:byte N"), the file name's bytes as they are: JSON writes them by its
  // reversible rule (docs/formats.md), text by printable().
  std::string at(int index) const;
  int size() const { return total_; }

 private:
  struct Part {
    std::string file;
    std::shared_ptr<const std::vector<int>> lines;
    bool bytes = false;
  };
  std::vector<Part> parts_;
  int total_ = 0;
};

struct MeshFrame {
  int index = 0;
  std::string file;
  std::vector<Vec3> cloth, obstacle;
  Places cloth_vertices, cloth_tris, obstacle_vertices, obstacle_tris;
};

class MeshSequence {
 public:
  // `frames`: the arguments for frame_files, or MESH CACHE: a mesh file that gives the faces and
  // a point cache (.pc2, .mdd) that gives every frame's positions of its vertices, one point per
  // vertex (a vertex's place is then its line in MESH). `cloth`: the object that is the cloth; ""
  // for the object named `cloth` if frame 0 has one, else the whole file. Every other object of the
  // frame files is an obstacle that moves per frame. `obstacles`: each a file (a fixed obstacle) or
  // a folder of as many OBJ files as there are frames (one per frame). Reads frame 0 and the fixed
  // obstacles and checks them: the cloth named exists, no vertex is both cloth and obstacle, the
  // cloth is manifold (no edge in more than two triangles). Throws InputError.
  MeshSequence(const std::vector<std::string>& frames, const std::string& cloth,
               const std::vector<std::string>& obstacles);
  ~MeshSequence();
  MeshSequence(const MeshSequence&) = delete;
  MeshSequence& operator=(const MeshSequence&) = delete;

  int frames() const;
  const std::vector<std::string>& files() const;
  const SequenceTopology& topology() const;
  // The cloth's object name as chosen ("" for the whole file).
  const std::string& cloth_name() const;
  // Faces of more than three corners, fan-triangulated: the most in any one frame read so far
  // (its frame file and the obstacle files), frame 0 once constructed.
  long polygons() const;
  // What the output says of how the input was read: a bake folder's frames and fixed obstacles,
  // a point cache's format and frames. One line each, no newline.
  const std::vector<std::string>& notes() const;

  // Frame i (0 <= i < frames()): read and checked against frame 0 (the same objects, vertex count
  // and faces, a triangle's corners in the same cyclic order; InputError naming the face or the
  // vertex otherwise). The first read(0) hands over frame 0 as
  // the constructor read it; later ones read it again.
  MeshFrame read(int i) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fdh::verify
