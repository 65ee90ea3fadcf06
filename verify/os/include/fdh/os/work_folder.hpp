// A folder a resumable job owns for one run (fuzz's OUT/.fuzz): WORK/lock, held (flock) by the
// run and its workers for the whole run, and WORK/tmp/, where every temporary file of every run
// goes and nothing else. Files are written there, synced, then renamed into place; under the
// lock no live run owns a temporary, so whatever is left in tmp/ is a killed run's.
//
// No link is ever followed inside it: WORK and tmp/ are opened with O_NOFOLLOW and kept open,
// the lock, the temporaries and the folders on the way to a file inside WORK are reached from
// those descriptors (openat), and a link where one of them belongs is refused with a message.
#pragma once

#include <memory>
#include <string>

#include "fdh/os/file_lock.hpp"

namespace fdh::verify {

class WorkFolder {
 public:
  // Makes WORK (and its parents) and WORK/tmp, and takes the lock, waiting up to
  // `lock_wait_seconds`. Throws LockBusy when another run holds it, std::runtime_error naming
  // the path on I/O failure or when WORK, tmp/ or the lock is a link or not what it should be.
  WorkFolder(const std::string& dir, double lock_wait_seconds);
  ~WorkFolder();
  WorkFolder(const WorkFolder&) = delete;
  WorkFolder& operator=(const WorkFolder&) = delete;

  const std::string& dir() const { return dir_; }
  const std::string& lock_path() const { return lock_path_; }

  // Empties tmp/ (removing links, never following them). Called once the run knows it will go
  // on, so that a run that refuses changes nothing.
  void clear_stale_temporaries() const;

  // Makes WORK/NAME a folder (NAME: one component), refusing a link there.
  void make_subfolder(const std::string& name) const;

  // `text` into `target` whole: a temporary in tmp/, synced, then renamed over `target`, which
  // must be absent or a regular file. A target inside WORK is reached from WORK's descriptor,
  // through no link.
  void write_whole(const std::string& target, const std::string& text) const;

 private:
  std::string dir_, lock_path_, tmp_;
  int dir_fd_ = -1, tmp_fd_ = -1;
  std::unique_ptr<FileLock> lock_;
};

// Throws std::runtime_error when `path` is a symbolic link: something in a work folder that
// fdhcert never follows (`what` says what belongs there).
void refuse_link(const std::string& path, const std::string& what);

}  // namespace fdh::verify
