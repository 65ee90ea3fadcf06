#include "cache_header.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "fdh/io/input_error.hpp"

namespace fdh::verify {

CacheHeader::CacheHeader(const std::string& path, std::size_t n) : path_(path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, 0, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  in.seekg(0, std::ios::end);
  size_ = std::uint64_t(in.tellg());
  in.seekg(0);
  bytes_.resize(std::size_t(std::min<std::uint64_t>(n, size_)));
  in.read(reinterpret_cast<char*>(bytes_.data()), std::streamsize(bytes_.size()));
  if (!in) throw InputError(path, 0, "cannot read the file");
}

void CacheHeader::need(std::size_t n, const char* format) const {
  if (bytes_.size() < n)
    fail(bytes_.size(), std::string("the file ends inside the ") + format + " header (" +
                            std::to_string(n) + " bytes)");
}

std::int32_t CacheHeader::int32(std::size_t at, bool big) const {
  std::uint32_t u = 0;
  for (int i = 0; i < 4; ++i)
    u |= std::uint32_t(bytes_[at + std::size_t(big ? i : 3 - i)]) << (8 * (3 - i));
  return std::int32_t(u);
}

float CacheHeader::float32(std::size_t at, bool big) const {
  const auto u = std::uint32_t(int32(at, big));
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

void CacheHeader::fail(std::uint64_t at, const std::string& what) const {
  throw InputError(path_, 0, "byte " + std::to_string(at) + ": " + what);
}

void CacheHeader::check_size(PointCache& c, std::uint64_t header, const char* frames_word) const {
  c.data = header;
  // Both counts are below 2^31, so the points' bytes fit in 64 bits.
  const std::uint64_t points = std::uint64_t(c.frames) * std::uint64_t(c.points) * 12;
  if (size_ - std::min(size_, header) == points) return;
  fail(header, std::to_string(c.frames) + " " + frames_word + " of " + std::to_string(c.points) +
                   " points need " + std::to_string(points) + " bytes after the " +
                   std::to_string(header) + "-byte header, and the file has " +
                   std::to_string(size_ - std::min(size_, header)) +
                   " (a size that does not match its header)");
}

}  // namespace fdh::verify
