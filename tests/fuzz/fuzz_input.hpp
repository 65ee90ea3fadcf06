// What the fuzz targets share: the readers take a path, so each input is written to one
// temporary file per process, reused from run to run, and removed at exit.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "fdh/io/input_error.hpp"

namespace fdh::fuzz {

// A file in $TMPDIR (else /tmp) named fdh-fuzz-XXXXXX<suffix>.
class InputFile {
 public:
  explicit InputFile(const char* suffix) {
    const char* dir = std::getenv("TMPDIR");
    path_ = std::string(dir && *dir ? dir : "/tmp") + "/fdh-fuzz-XXXXXX" + suffix;
    fd_ = mkstemps(path_.data(), int(std::char_traits<char>::length(suffix)));
    if (fd_ < 0) {
      std::perror(path_.c_str());
      std::abort();
    }
  }
  ~InputFile() {
    close(fd_);
    unlink(path_.c_str());
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // Replaces the file's content by the input and returns its path.
  const std::string& write(const std::uint8_t* data, std::size_t size) {
    if (ftruncate(fd_, 0) != 0) fail("truncate");
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = pwrite(fd_, data + done, size - done, off_t(done));
      if (n <= 0) fail("write");
      done += std::size_t(n);
    }
    return path_;
  }

 private:
  [[noreturn]] void fail(const char* what) const {
    std::perror((std::string(what) + " " + path_).c_str());
    std::abort();
  }
  std::string path_;
  int fd_ = -1;
};

// Runs `read`: an InputError is the reader's normal answer to bad input; any other exception is
// a finding, reported by abort() so that libFuzzer saves the input.
template <class Read>
void only_input_errors(Read&& read) {
  try {
    read();
  } catch (const verify::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not an InputError: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: a non-standard exception\n");
    std::abort();
  }
}

}  // namespace fdh::fuzz
