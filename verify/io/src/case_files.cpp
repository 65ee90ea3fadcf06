#include "fdh/io/case_files.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "fdh/io/case_hash.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {

std::string case_hash(const Query& q) {
  CaseHash h;
  h.add(q.kind == QueryKind::VertexFace ? 1 : 2);
  for (const Vec3& p : q.x)
    for (int c = 0; c < 3; ++c) h.add_coordinate(p[c]);
  // Only at δ > 0: every case stored before δ existed keeps its name.
  if (q.min_distance != 0) h.add_coordinate(q.min_distance);
  return h.hex();
}

std::string case_file_text(const QueryRecord& r, const std::vector<std::string>& comments) {
  std::ostringstream os;
  for (const std::string& c : comments) os << "# " << c << '\n';
  write_native(os, r);
  return os.str();
}

std::vector<std::string> list_query_files(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  // A link loop (ELOOP) or a folder on the way that cannot be entered is not "no such file".
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw InputError(path, 0, "cannot be read: " + ec.message());
  if (!fs::exists(st)) throw InputError(path, 0, "no such file or folder");
  // A file, a FIFO or a device: the reader takes it or refuses it (InputFile).
  if (!fs::is_directory(st)) return {path};
  return files_below(path, ".vf");
}

std::vector<std::string> files_below(const std::string& dir, const std::string& extension) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<std::string> files;
  fs::recursive_directory_iterator it(dir, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    std::error_code entry;  // a broken link is no case file, and no reason to stop
    if (it->is_regular_file(entry) && it->path().extension() == extension)
      files.push_back(it->path().string());
  }
  if (ec) throw InputError(dir, 0, "cannot list the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace fdh::verify
