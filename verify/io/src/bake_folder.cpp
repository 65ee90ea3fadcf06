#include "fdh/io/bake_folder.hpp"

#include <algorithm>
#include <filesystem>
#include <map>

#include "fdh/io/input_error.hpp"
#include "fdh/io/mesh_sequence.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](char c) { return char(c | 0x20); });
  return s;
}

// The stem of a numbered file name, its digits cut ("cloth_" of "cloth_00012.obj"); false if
// the name does not end in digits before the extension.
bool numbered_stem(const fs::path& p, std::string& stem) {
  const std::string s = p.stem().string();
  std::size_t i = s.size();
  while (i > 0 && s[i - 1] >= '0' && s[i - 1] <= '9') --i;
  stem = s.substr(0, i);
  return i < s.size();
}

std::string file_list(const std::vector<std::string>& files) {
  std::string s;
  for (const std::string& f : files) s += (s.empty() ? "" : ", ") + fs::path(f).filename().string();
  return s;
}

}  // namespace

bool is_mesh_file(const std::string& path) {
  const std::string ext = lower(fs::path(path).extension().string());
  return ext == ".obj" || ext == ".ply";
}

std::string BakeFolder::roles(const std::string& folder) const {
  if (obstacles.empty()) return "";
  return printable(folder) + ": the frames are " + printable(stem) + "*" + printable(ext) + " (" +
         std::to_string(frames.size()) +
         " files); fixed obstacles: " + printable(file_list(obstacles));
}

BakeFolder read_bake_folder(const std::string& folder) {
  std::error_code ec;
  std::vector<std::string> all;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    std::error_code entry;  // a link loop among the files is read (and refused) as a file
    if (!e.is_directory(entry) && is_mesh_file(e.path().string())) all.push_back(e.path().string());
  }
  if (ec) throw InputError(folder, 0, "cannot list the folder: " + ec.message());
  if (all.empty()) throw InputError(folder, 0, "a folder without an .obj or .ply file");
  std::sort(all.begin(), all.end(), natural_less);
  std::map<std::pair<std::string, std::string>, int> groups;  // (stem, extension): files
  for (const std::string& f : all) {
    std::string stem;
    if (numbered_stem(f, stem)) ++groups[{stem, lower(fs::path(f).extension().string())}];
  }
  BakeFolder b;
  if (groups.empty()) return b.frames = all, b;
  if (groups.size() > 1) {
    std::string names;
    for (const auto& [g, n] : groups)
      names +=
          (names.empty() ? "" : ", ") + g.first + "*" + g.second + " (" + std::to_string(n) + ")";
    throw InputError(folder, 0,
                     "numbered files of more than one name: " + printable(names) +
                         "; pass the cloth's frames as files, a moving obstacle's folder with "
                         "--obstacle");
  }
  const auto& [stem, ext] = groups.begin()->first;
  for (const std::string& f : all) {
    std::string s;
    const bool frame =
        numbered_stem(f, s) && s == stem && lower(fs::path(f).extension().string()) == ext;
    (frame ? b.frames : b.obstacles).push_back(f);
  }
  b.stem = stem, b.ext = fs::path(b.frames.front()).extension().string();
  return b;
}

}  // namespace fdh::verify
