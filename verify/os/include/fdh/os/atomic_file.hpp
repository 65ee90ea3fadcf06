// Files are written whole: a temporary file beside the target, then a rename. A reader (or a
// crash) never sees half a file. Only regular files are ever replaced: an existing device,
// FIFO, socket or folder at an output path is refused, never renamed over.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "fdh/os/temporaries.hpp"

namespace fdh::verify {

// Throws std::runtime_error naming the path and the system's reason when the file cannot be
// written, or when the path exists and is not a regular file. Leaves no temporary file.
void write_file_atomically(const std::string& path, const std::string& content);
// The same with the temporary file made in `temp_dir` (on the same file system as `path`), for
// a run that clears its own temporaries (fdh/os/work_folder.hpp).
void write_file_atomically(const std::string& path, const std::string& content,
                           const std::string& temp_dir);

// Whether `path` is a regular file (not a link) holding exactly `text`: a write that would
// change nothing.
bool file_holds(const std::string& path, const std::string& text);

// Writes all of `data` to `fd`, retrying short writes; false with errno set on failure.
// Async-signal-safe (write(2) only): a forked child may call it.
bool write_all(int fd, std::string_view data);

// Checks, before a run writes anything, that `path` can take an output file: it is absent or a
// regular file (a symbolic link is judged by its target), and its folder exists and is
// writable, or, with `folder_made_by_run`, the folder is absent (the run creates it) under a
// writable folder. Throws std::runtime_error naming the path and what is wrong.
void check_output_path(const std::string& path, bool folder_made_by_run = false);

// Checks that `dir` can take a run's outputs: it is a writable folder, or it is absent and can
// be created (the nearest existing ancestor is a writable folder). `files` are checked as with
// check_output_path inside it (they may name subfolders, such as "data/a.csv").
void check_output_dir(const std::string& dir, const std::vector<std::string>& files = {});

// "Out of memory" style text for an errno value.
std::string system_reason(int errno_value);

// A file written piece by piece but published whole: stream() writes to a temporary file
// beside `path` (recorded, so that SIGTERM and SIGINT remove it; what a dead run left beside
// `path` is removed first: fdh/os/temporaries.hpp); commit() renames it into place. Destroyed
// uncommitted, it leaves nothing. Every write is checked; commit() throws std::runtime_error with
// the path and the system's reason when any write, the flush or the close failed.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::ostream& stream();
  void commit();

  class Buffer;  // a std::streambuf over the temporary file's descriptor

 private:
  std::string path_, tmp_;
  RecordedTemporary recorded_;  // tmp_, for SIGTERM and SIGINT (fdh/os/temporaries.hpp)
  std::unique_ptr<Buffer> buf_;
  std::unique_ptr<std::ostream> out_;
  bool committed_ = false;
};

}  // namespace fdh::verify
