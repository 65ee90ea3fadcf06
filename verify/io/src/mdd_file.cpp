// LightWave's MDD point cache, as Blender's bundled add-on io_shape_mdd writes it: big-endian
// '>2i' frames and points, '>%df' a time per frame, then '>fff' per point of every frame.
#include "cache_header.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/point_cache.hpp"

namespace fdh::verify {

PointCache open_mdd(const std::string& path) {
  const CacheHeader h(path, 8);
  h.need(8, "MDD");
  PointCache c;
  c.path = path, c.format = "MDD", c.big_endian = true;
  c.frames = h.int32(0, true);
  if (c.frames < 1) h.fail(0, std::to_string(c.frames) + " frames; a cache needs at least 1");
  c.points = h.int32(4, true);
  if (c.points < 1) h.fail(4, std::to_string(c.points) + " points; a cache needs at least 1");
  const std::uint64_t header = 8 + 4 * std::uint64_t(c.frames);  // and the frame times
  if (h.size() < header)
    h.fail(h.size(), "the file ends inside the frame times (" + std::to_string(c.frames) +
                         " frames need " + std::to_string(header) + " bytes of header)");
  h.check_size(c, header, "frames");
  return c;
}

}  // namespace fdh::verify
