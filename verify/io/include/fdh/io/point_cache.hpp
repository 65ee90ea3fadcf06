// A point cache: the positions of a mesh's vertices frame after frame, in a file of its own, as
// Blender's bundled add-ons export them (io_export_pc2: PC2; io_shape_mdd: LightWave's MDD, read
// by Modo and three.js). The faces come from the mesh it is audited with:
// `fdhcert audit MESH.obj CACHE.pc2`. A frame is read when it is asked for, so a cache of any
// length streams.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fdh/vec3.hpp"

namespace fdh::verify {

struct PointCache {
  std::string path;
  const char* format = "";  // "PC2" or "MDD"
  int points = 0;           // per frame
  int frames = 0;
  std::uint64_t data = 0;  // the byte offset of frame 0's first point
  bool big_endian = false;
};

// A PC2 or MDD file, by its extension (any case).
bool is_point_cache(const std::string& path);

// Reads the header and checks that the file's size is the header's and its points' exactly.
// Throws InputError "FILE: byte N: what" on a bad header or a size that does not match.
PointCache open_point_cache(const std::string& path);

// Blender's PC2 (io_export_pc2): little-endian; `POINTCACHE2\0`, version 1, points, start frame
// (float), sampling rate (float), samples; then float32 x, y, z of every point of every sample.
PointCache open_pc2(const std::string& path);

// MDD (io_shape_mdd): big-endian; frames, points, a float32 time per frame; then float32 x, y, z
// of every point of every frame.
PointCache open_mdd(const std::string& path);

// The byte offset of point p of frame i.
std::uint64_t cache_offset(const PointCache& c, int frame, int point);

// Frame i's points, exactly as the file's float32 values. Throws InputError at the byte of a
// value that is not a finite number, or when the file cannot be read.
std::vector<Vec3> read_cache_frame(const PointCache& c, int frame);

}  // namespace fdh::verify
