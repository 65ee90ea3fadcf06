#include "fdh/os/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace fdh::verify {

FileLock::FileLock(const std::string& path, double wait_seconds)
    : FileLock(AT_FDCWD, path, path, wait_seconds) {}

FileLock::FileLock(int dir_fd, const std::string& name, const std::string& path,
                   double wait_seconds) {
  fd_ = ::openat(dir_fd, name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
  if (fd_ < 0 && errno == ELOOP)
    throw std::runtime_error(path + ": is a symbolic link, not a lock file; refusing to follow it");
  if (fd_ < 0)
    throw std::runtime_error(path + ": cannot open the lock file: " + std::strerror(errno));
  lock(path, wait_seconds);
}

void FileLock::lock(const std::string& path, double wait_seconds) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_seconds);
  while (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    if (errno == EINTR) continue;
    const int err = errno;
    if (err != EWOULDBLOCK || std::chrono::steady_clock::now() >= deadline) {
      ::close(fd_);
      if (err != EWOULDBLOCK)
        throw std::runtime_error(path + ": cannot lock: " + std::strerror(err));
      throw LockBusy(path + ": held by another process");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

FileLock::~FileLock() {
  ::close(fd_);
}

}  // namespace fdh::verify
