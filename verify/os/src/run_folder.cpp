#include "fdh/os/run_folder.hpp"

#include "fdh/os/work_folder.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

const std::string kMarkerPrefix = "cases-";

}  // namespace

std::string Manifest::text() const {
  std::string out = title + "\n";
  for (const auto& [key, value] : entries) out += key + " " + value + "\n";
  return out;
}

std::optional<Manifest> Manifest::read(const std::string& path, const std::string& title) {
  std::ifstream in(path);
  Manifest m;
  if (!std::getline(in, m.title) || m.title != title) return std::nullopt;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string key, value;
    if (!(words >> key)) continue;
    if (!(words >> value)) return std::nullopt;
    m.entries.emplace_back(key, value);
  }
  return m;
}

std::string marker_name(IndexRange r) {
  return kMarkerPrefix + std::to_string(r.begin) + "-" + std::to_string(r.end);
}

std::optional<IndexRange> parse_marker_name(const std::string& name) {
  IndexRange r;
  char dash = 0;
  std::istringstream in(name.rfind(kMarkerPrefix, 0) == 0 ? name.substr(kMarkerPrefix.size())
                                                          : std::string());
  if (!(in >> r.begin >> dash >> r.end) || dash != '-' || in.peek() != EOF) return std::nullopt;
  if (r.begin < 0 || r.end <= r.begin || name != marker_name(r)) return std::nullopt;
  return r;
}

long Coverage::done_count() const {
  long n = 0;
  for (const DoneMarker& m : done) n += m.range.end - m.range.begin;
  return n;
}

Coverage coverage_of(const std::string& run_dir, long first, long last) {
  std::vector<DoneMarker> all;
  std::error_code ec;
  for (fs::directory_iterator it(run_dir, ec), end; !ec && it != end; it.increment(ec))
    if (const std::optional<IndexRange> r = parse_marker_name(it->path().filename().string())) {
      refuse_link(it->path().string(), "a done-marker");
      if (r->begin >= first && r->end <= last) all.push_back({*r, it->path().string()});
    }
  if (ec) throw std::runtime_error(run_dir + ": cannot list: " + ec.message());
  std::sort(all.begin(), all.end(), [](const DoneMarker& a, const DoneMarker& b) {
    return a.range.begin != b.range.begin ? a.range.begin < b.range.begin
                                          : a.range.end > b.range.end;
  });
  // Markers never overlap (one run at a time, gaps only are run); were they to, the first wins.
  Coverage c;
  long covered = first;
  for (const DoneMarker& m : all) {
    if (m.range.begin < covered) continue;
    if (m.range.begin > covered) c.todo.push_back({covered, m.range.begin});
    c.done.push_back(m);
    covered = m.range.end;
  }
  if (covered < last) c.todo.push_back({covered, last});
  return c;
}

std::vector<std::string> run_folders(const std::string& dir, const std::string& except) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename() == except) continue;
    refuse_link(it->path().string(), "a run's folder");
    if (it->is_directory()) out.push_back(it->path().string());
  }
  if (ec) throw std::runtime_error(dir + ": cannot list: " + ec.message());
  return out;
}

}  // namespace fdh::verify
