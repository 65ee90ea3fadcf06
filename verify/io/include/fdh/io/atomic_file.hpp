// Files are written whole: a temporary file beside the target, then a rename. A reader (or a
// crash) never sees half a file.
#pragma once

#include <string>

namespace fdh::verify {

// Throws std::runtime_error naming the path when the file cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace fdh::verify

#include <fstream>

namespace fdh::verify {

// A file written piece by piece but published whole: stream() writes to a temporary file
// beside `path`; commit() renames it into place. Destroyed uncommitted, it leaves nothing.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::ofstream& stream() { return out_; }
  void commit();  // throws std::runtime_error naming the path

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace fdh::verify
