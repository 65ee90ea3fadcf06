// What gnuplot draws a chart into, and the check of it before it is published (charts.cpp):
// a private folder beside the chart, and a PNG or SVG read whole.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fdh/os/temporaries.hpp"

namespace fdh::verify {

// "" if `bytes` is a whole PNG: the signature, then chunks (length, type, data, CRC-32 checked)
// up to IEND, which ends the file; otherwise what is wrong, in words.
std::string png_problem(std::string_view bytes);

// "" if `bytes` is an SVG that ends with `</svg>` (and blanks); otherwise what is wrong.
std::string svg_problem(std::string_view bytes);

// A folder only this user can enter, DIR/NAME.tmp.<pid>.XXXXXX (mkdtemp, mode 0700), made
// beside a chart so that no one can plant a link at a name gnuplot opens. It and the files
// expected in it are recorded (SIGTERM and SIGINT remove them: fdh/os/temporaries.hpp) and
// removed by the destructor; a file is read and renamed out of it through the folder's own
// descriptor, never through a link.
class PrivateFolder {
 public:
  // Throws std::runtime_error naming DIR and the system's reason.
  PrivateFolder(const std::string& dir, const std::string& name);
  ~PrivateFolder();
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;

  // The folder's name, relative to DIR.
  const std::string& name() const { return name_; }
  // Records `file`, a name in the folder, before something writes it.
  void expect(const std::string& file);
  // The bytes of `file` if it is a regular file in the folder.
  std::optional<std::string> read(const std::string& file) const;
  // Whether a write of 64 KiB succeeds in the folder: "" or the system's reason ("No space
  // left on device"), for a chart that came out cut.
  std::string write_probe();
  // Renames `file` onto `target`; throws std::runtime_error naming the target.
  void publish(const std::string& file, const std::string& target);

 private:
  std::string path_, name_;
  int fd_ = -1;
  RecordedTemporary recorded_;
  std::vector<std::string> files_;
  std::vector<RecordedTemporary> recorded_files_;
};

}  // namespace fdh::verify
