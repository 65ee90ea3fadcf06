// A folder a resumable job owns for one run (fuzz's OUT/.fuzz): WORK/lock, held (flock) by the
// run and its workers for the whole run, and WORK/tmp/, where every temporary file of every run
// goes and nothing else. Files are written there, synced, then renamed into place; under the
// lock no live run owns a temporary, so whatever is left in tmp/ is a killed run's.
#pragma once

#include <string>

#include "fdh/os/file_lock.hpp"

namespace fdh::verify {

class WorkFolder {
 public:
  // Makes WORK (and its parents) and WORK/tmp, and takes the lock, waiting up to
  // `lock_wait_seconds`. Throws LockBusy when another run holds it, std::runtime_error naming
  // the path on I/O failure or when tmp/ is not a folder of its own (it is emptied).
  WorkFolder(const std::string& dir, double lock_wait_seconds);

  const std::string& dir() const { return dir_; }
  const std::string& lock_path() const { return lock_path_; }

  // Empties tmp/. Called once the run knows it will go on, so that a run that refuses changes
  // nothing.
  void clear_stale_temporaries() const;

  // `text` into `target` whole: a temporary in tmp/, synced, then renamed over `target`, which
  // must be absent or a regular file.
  void write_whole(const std::string& target, const std::string& text) const;

 private:
  std::string dir_, lock_path_, tmp_;
  FileLock lock_;
};

}  // namespace fdh::verify
