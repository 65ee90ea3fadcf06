#include "fdh/io/point_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "fdh/io/input_error.hpp"

namespace fdh::verify {

bool is_point_cache(const std::string& path) {
  std::string ext = path.substr(std::min(path.size(), path.rfind('.')));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](char c) { return char(c | 0x20); });
  return ext == ".pc2" || ext == ".mdd";
}

PointCache open_point_cache(const std::string& path) {
  std::string ext = path.substr(path.rfind('.'));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](char c) { return char(c | 0x20); });
  return ext == ".pc2" ? open_pc2(path) : open_mdd(path);
}

std::uint64_t cache_offset(const PointCache& c, int frame, int point) {
  return c.data + (std::uint64_t(frame) * std::uint64_t(c.points) + std::uint64_t(point)) * 12;
}

namespace {

float float32(const unsigned char* p, bool big) {
  std::uint32_t u = 0;
  for (int i = 0; i < 4; ++i) u |= std::uint32_t(p[big ? i : 3 - i]) << (8 * (3 - i));
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

}  // namespace

std::vector<Vec3> read_cache_frame(const PointCache& c, int frame) {
  std::ifstream in(c.path, std::ios::binary);
  const std::uint64_t at = cache_offset(c, frame, 0);
  std::vector<unsigned char> bytes(std::size_t(c.points) * 12);
  in.seekg(std::streamoff(at));
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!in || std::size_t(in.gcount()) != bytes.size())
    throw InputError(c.path, 0,
                     "byte " + std::to_string(at) + ": cannot read frame " + std::to_string(frame) +
                         " (the file changed or cannot be read)");
  std::vector<Vec3> x(std::size_t(c.points));
  for (std::size_t p = 0; p < x.size(); ++p) {
    double v[3];
    for (std::size_t k = 0; k < 3; ++k) {
      v[k] = double(float32(&bytes[p * 12 + k * 4], c.big_endian));
      if (!std::isfinite(v[k]))
        throw InputError(c.path, 0,
                         "byte " + std::to_string(at + p * 12 + k * 4) + ": frame " +
                             std::to_string(frame) + ", point " + std::to_string(p) +
                             ", coordinate " + std::to_string(k + 1) + ": not a finite number");
    }
    x[p] = {v[0], v[1], v[2]};
  }
  return x;
}

}  // namespace fdh::verify
