// Blender's PC2 point cache, as its bundled add-on io_export_pc2 writes it (struct '<12siiffi':
// signature, version, points, start frame, sampling, samples; then '<fff' per point).
#include <cstring>

#include "cache_header.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/point_cache.hpp"

namespace fdh::verify {

PointCache open_pc2(const std::string& path) {
  const CacheHeader h(path, 32);
  static const char kSignature[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};
  if (h.bytes().size() < 12 || std::memcmp(h.bytes().data(), kSignature, 12) != 0)
    h.fail(0, "not a PC2 file: it must begin with 'POINTCACHE2' and a zero byte");
  h.need(32, "PC2");
  if (const std::int32_t version = h.int32(12, false); version != 1)
    h.fail(12, "PC2 version " + std::to_string(version) + "; only version 1 is known");
  PointCache c;
  c.path = path, c.format = "PC2", c.big_endian = false;
  c.points = h.int32(16, false);
  if (c.points < 1) h.fail(16, std::to_string(c.points) + " points; a cache needs at least 1");
  c.frames = h.int32(28, false);
  if (c.frames < 1) h.fail(28, std::to_string(c.frames) + " samples; a cache needs at least 1");
  h.check_size(c, 32, "samples");
  return c;
}

}  // namespace fdh::verify
