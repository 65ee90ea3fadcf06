// Reading a PLY (Stanford polygon) file as a triangle mesh, for `fdhcert audit`: ascii, binary
// little-endian and binary big-endian; the `vertex` element's x, y, z (float or double) and the
// `face` element's `vertex_indices` (or `vertex_index`) lists. Every other element and property
// is skipped. Read whole, within FDH_MAX_FILE_BYTES (docs/limits.md).
#pragma once

#include <string>

#include "fdh/io/obj_file.hpp"

namespace fdh::verify {

// Reads `path` into the OBJ reader's mesh: one object named "" (the whole file), a face of n > 3
// corners split into the fan (0, i, i+1) and counted in `polygons`. The places of an ascii file
// are its lines; of a binary file the byte offset of each vertex and face (`byte_offsets`).
// Throws InputError: a bad header at its line; in the body, the line (ascii) or the byte offset
// (binary) and what is wrong: a value that is not a finite number, an index that is out of range
// or names a vertex twice, a file that ends early or goes on past the last element.
ObjFile read_ply(const std::string& path);

}  // namespace fdh::verify
