#include "fdh/io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <stdexcept>

namespace fdh::verify {
namespace {

std::string temp_path(const std::string& path) {
  static std::atomic<unsigned long> serial{0};  // unique per call: threads may write at once
  return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(serial++);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = temp_path(path);
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

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), tmp_(temp_path(path_)) {
  out_.open(tmp_, std::ios::binary);
  if (!out_) throw std::runtime_error(path_ + ": cannot write file");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::remove(tmp_.c_str());
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = bool(out_);
  out_.close();
  if (!ok || std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    std::remove(tmp_.c_str());
    committed_ = true;  // nothing left to remove
    throw std::runtime_error(path_ + ": cannot write file");
  }
  committed_ = true;
}

}  // namespace fdh::verify
