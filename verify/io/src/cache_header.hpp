// The start of a point cache file (fdh/io/point_cache.hpp), for its format's reader: the file's
// size, its first bytes decoded in either byte order, and the size check every format makes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fdh/io/point_cache.hpp"

namespace fdh::verify {

class CacheHeader {
 public:
  // Reads up to `n` bytes of `path`. Throws InputError when it cannot be opened.
  CacheHeader(const std::string& path, std::size_t n);

  std::uint64_t size() const { return size_; }
  // Throws "FILE: byte N: the file ends inside the FORMAT header" when the file is shorter.
  void need(std::size_t n, const char* format) const;
  const std::vector<unsigned char>& bytes() const { return bytes_; }
  std::int32_t int32(std::size_t at, bool big) const;
  float float32(std::size_t at, bool big) const;
  [[noreturn]] void fail(std::uint64_t at, const std::string& what) const;

  // `c` with c.points and c.frames set: c.data = `header`, and the file must hold exactly the
  // header and every frame's points (12 bytes each).
  void check_size(PointCache& c, std::uint64_t header, const char* frames_word) const;

 private:
  std::string path_;
  std::uint64_t size_ = 0;
  std::vector<unsigned char> bytes_;
};

}  // namespace fdh::verify
