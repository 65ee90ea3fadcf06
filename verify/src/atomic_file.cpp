#include "fdh/verify/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <stdexcept>

namespace fdh::verify {

void write_file_atomically(const std::string& path, const std::string& content) {
  static std::atomic<unsigned long> serial{0};  // unique per call: threads may write at once
  const std::string tmp =
      path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(serial++);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error(path + ": cannot write file");
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size() &&
                       std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write file");
  }
}

}  // namespace fdh::verify
