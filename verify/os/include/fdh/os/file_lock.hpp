// An exclusive lock on a file (flock), held while the object lives. Forked children inherit it:
// the lock is free only once every process that holds its descriptor has ended.
#pragma once

#include <stdexcept>
#include <string>

namespace fdh::verify {

// Another process held the lock for the whole wait.
struct LockBusy : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class FileLock {
 public:
  // Opens (creating it; never through a symbolic link) and locks `path`, waiting up to
  // `wait_seconds` for another holder to let go. Throws LockBusy when it does not,
  // std::runtime_error naming the path when the file cannot be opened or locked.
  FileLock(const std::string& path, double wait_seconds);
  // The same for `name` in the folder open as `dir_fd` (openat): no link on the way is followed.
  // `path` names the file in messages.
  FileLock(int dir_fd, const std::string& name, const std::string& path, double wait_seconds);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  void lock(const std::string& path, double wait_seconds);
  int fd_ = -1;
};

}  // namespace fdh::verify
