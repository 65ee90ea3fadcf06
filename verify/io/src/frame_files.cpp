// Which files are a sequence's frames (files, folders, bake folders), each read by its format,
// in natural order, and the places (FILE:LINE or FILE:byte N) of a frame's primitives.
#include <algorithm>
#include <filesystem>

#include "fdh/io/bake_folder.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/mesh_sequence.hpp"
#include "fdh/io/ply_file.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

std::vector<std::string> frame_files(const std::vector<std::string>& args,
                                     std::vector<std::string>* fixed,
                                     std::vector<std::string>* notes) {
  std::vector<std::string> out;
  for (const std::string& a : args) {
    std::error_code ec;
    const fs::file_status st = fs::status(a, ec);
    // A link loop (ELOOP) or a folder on the way that cannot be entered is not "no such file".
    if (ec && ec != std::errc::no_such_file_or_directory)
      throw InputError(a, 0, "cannot be read: " + ec.message());
    if (!fs::exists(st)) throw InputError(a, 0, "no such file or folder");
    if (!fs::is_directory(st)) {
      out.push_back(a);
      continue;
    }
    const BakeFolder b = read_bake_folder(a);
    if (!b.obstacles.empty() && !fixed)
      throw InputError(a, 0,
                       "un-numbered files beside numbered frames: " + b.roles(a).substr(a.size()));
    if (fixed) fixed->insert(fixed->end(), b.obstacles.begin(), b.obstacles.end());
    if (notes && !b.obstacles.empty()) notes->push_back(b.roles(a));
    out.insert(out.end(), b.frames.begin(), b.frames.end());
  }
  return out;
}

ObjFile read_mesh(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](char c) { return char(c | 0x20); });
  return ext == ".ply" ? read_ply(path) : read_obj(path);
}

namespace {

bool digit(char c) {
  return c >= '0' && c <= '9';
}

// Compares the digit runs starting at a[i] and b[j] as numbers; moves i and j past them.
int compare_numbers(const std::string& a, std::size_t& i, const std::string& b, std::size_t& j) {
  while (i < a.size() && a[i] == '0' && i + 1 < a.size() && digit(a[i + 1])) ++i;
  while (j < b.size() && b[j] == '0' && j + 1 < b.size() && digit(b[j + 1])) ++j;
  std::size_t ei = i, ej = j;
  while (ei < a.size() && digit(a[ei])) ++ei;
  while (ej < b.size() && digit(b[ej])) ++ej;
  int c = ei - i < ej - j ? -1 : ei - i > ej - j ? 1 : a.compare(i, ei - i, b, j, ej - j);
  i = ei, j = ej;
  return c < 0 ? -1 : c > 0 ? 1 : 0;
}

}  // namespace

bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (digit(a[i]) && digit(b[j])) {
      if (const int c = compare_numbers(a, i, b, j)) return c < 0;
    } else {
      if (a[i] != b[j]) return (unsigned char)a[i] < (unsigned char)b[j];
      ++i, ++j;
    }
  }
  if (i < a.size() || j < b.size()) return j < b.size();
  return a < b;  // equal as numbers ("02", "2"): byte order
}

void Places::add(std::string file, std::shared_ptr<const std::vector<int>> lines, bool bytes) {
  total_ += int(lines->size());
  parts_.push_back({std::move(file), std::move(lines), bytes});
}

std::string Places::at(int index) const {
  for (const Part& p : parts_) {
    if (index < int(p.lines->size())) {
      const int n = (*p.lines)[std::size_t(index)];  // -1: past an int's bytes
      return p.file + (p.bytes ? ":byte " : ":") + (n < 0 ? "?" : std::to_string(n));
    }
    index -= int(p.lines->size());
  }
  return "?";
}

}  // namespace fdh::verify
