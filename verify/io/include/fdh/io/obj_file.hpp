// Reading a Wavefront OBJ file as a triangle mesh, for `fdhcert audit`: `v` and `f` lines, the
// objects named by `o` and `g`, comments, CRLF, a UTF-8 byte-order mark; the specification's other
// statements (vt, vn, s, usemtl, l, ...) are read past, and any other first word is an error.
// Read within the bounds of docs/limits.md (FDH_MAX_FILE_BYTES, FDH_MAX_LINE_BYTES).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/vec3.hpp"

namespace fdh::verify {

// The faces under one name (`o NAME` or `g NAME`; the same name again adds to it). Faces before
// any `o` or `g` belong to the object named "".
struct ObjObject {
  std::string name;
  std::vector<Tri> tris;   // 0-based indices into ObjFile::x
  std::vector<int> lines;  // the `f` line of each triangle
};

struct ObjFile {
  std::string path;
  std::vector<Vec3> x;             // every `v`, in file order
  std::vector<int> vertex_lines;   // the line of each `v`
  std::vector<ObjObject> objects;  // in order of first appearance; only those with faces
  long polygons = 0;               // faces of more than 3 vertices, fan-triangulated
  bool byte_offsets = false;       // the lines are byte offsets (a binary file: PLY)

  // The object named `name`, or nullptr.
  const ObjObject* object(const std::string& name) const;
};

// Reads `path`. A face `f i j k ...` takes `v`, `v/vt`, `v/vt/vn` or `v//vn` per corner; an index
// counts from 1, a negative one back from the last `v` read so far. A face of n > 3 corners is
// split into the fan (0, i, i+1) and counted in `polygons`. Throws InputError (FILE:LINE: what)
// on a coordinate that is not a finite number, an index that is 0, not a number or out of range,
// a face of fewer than 3 corners, a face that names a vertex twice (degenerate), a statement
// that is not OBJ's, a UTF-16 or UTF-32 file, or a file past the bounds.
ObjFile read_obj(const std::string& path);

// A decimal, scientific or hex-float number, read the same in any locale (std::from_chars, else
// parse_double); a leading '+' is taken, a decimal below the smallest double rounds as strtod
// does. False for anything else, including "nan", "inf" and a number past the doubles.
bool parse_finite(std::string_view token, double& out);
// Why parse_finite refused `token`: "'x' is not a number", "... is not a finite number", "... is
// outside the range of a double".
std::string number_refusal(std::string_view token);

}  // namespace fdh::verify
