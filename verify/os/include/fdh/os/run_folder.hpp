// The folder of one resumable run: RUN/manifest, the parameters that fix its work (written
// before any of it), and done-markers RUN/cases-B-E, one per finished range [B, E) of the run's
// numbered items, each holding what the range found. Markers name ranges, not chunk numbers,
// so a run resumed with any chunk size or worker count does exactly the items no marker covers.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fdh::verify {

struct IndexRange {
  long begin = 0, end = 0;
};

// "TITLE\nkey value\n...": what a run records of its parameters.
struct Manifest {
  std::string title;
  std::vector<std::pair<std::string, std::string>> entries;  // in order; values hold no newline

  std::string text() const;
  // A manifest titled `title`; nullopt for a missing or unreadable file, another title or a line
  // without a value.
  static std::optional<Manifest> read(const std::string& path, const std::string& title);
};

// The name of the marker of [r.begin, r.end), and back (nullopt for any other name).
std::string marker_name(IndexRange r);
std::optional<IndexRange> parse_marker_name(const std::string& name);

struct DoneMarker {
  IndexRange range;
  std::string path;
};

// The markers of a run folder that cover [first, last) without overlapping (sorted), and the
// gaps between them: the items still to do.
struct Coverage {
  std::vector<DoneMarker> done;
  std::vector<IndexRange> todo;
  long done_count() const;
};

// Throws std::runtime_error naming the folder when it cannot be listed, or naming a marker that
// is a symbolic link (never followed).
Coverage coverage_of(const std::string& run_dir, long first, long last);

// The folders beside one another in `dir` (each a run's), apart from `except`. A symbolic link
// among them is refused (std::runtime_error), never followed.
std::vector<std::string> run_folders(const std::string& dir, const std::string& except);

}  // namespace fdh::verify
