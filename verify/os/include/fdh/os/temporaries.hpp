// This run's temporaries, recorded as they are made, so that SIGTERM, SIGINT or a last-resort
// error removes them; and the clean-up of the temporaries of a run that died (SIGKILL, power
// loss) by a later run that writes the same output. A temporary is named after its output:
// TARGET.tmp.<pid>.<n> for a file (fdh/os/atomic_file.hpp), TARGET.tmp.<pid>.XXXXXX for a
// private folder (mkdtemp; the charts', fdh/io/charts.hpp), TARGET.tmp.<pid>.staged-XXXXXX for
// a multi-file output's private folder, removed with all it holds (fdh/os/output_folder.hpp).
#pragma once

#include <sys/types.h>

#include <string>

namespace fdh::verify {

// One temporary of this process, recorded while the object lives; destroyed, it is forgotten
// (its owner renamed or removed it). A folder is removed after the files, and only if empty.
// At most 256 at once, paths under 4096 bytes: one beyond that is not recorded (a later run
// still removes it, as a dead run's).
class RecordedTemporary {
 public:
  RecordedTemporary() = default;
  explicit RecordedTemporary(const std::string& path, bool folder = false);
  // A folder removed with everything in it (a staged output: fdh/os/output_folder.hpp).
  static RecordedTemporary tree(const std::string& path);
  ~RecordedTemporary();
  RecordedTemporary(RecordedTemporary&& other) noexcept;
  RecordedTemporary& operator=(RecordedTemporary&& other) noexcept;
  RecordedTemporary(const RecordedTemporary&) = delete;
  RecordedTemporary& operator=(const RecordedTemporary&) = delete;

 private:
  int slot_ = -1;
};

// Removes the folder `path` and everything in it, links not followed (a link is removed, never
// its target); nothing at `path`, or a file there, is left alone. At most 64 folders deep.
// Async-signal-safe: a signal handler calls it for a recorded tree.
void remove_tree(const char* path) noexcept;

// Removes every recorded temporary: files first, then folders. Async-signal-safe.
void remove_recorded_temporaries() noexcept;

// Forgets them all without removing them: a forked child's copy of the record is its parent's.
void forget_recorded_temporaries() noexcept;

// SIGTERM and SIGINT remove the recorded temporaries, then end the process by the same signal
// with its default action (the conventional status 128 + signal). For fdhcert's main.
void remove_temporaries_on_signals();

// "TARGET.tmp.<pid>.<n>", this process's n-th temporary name for TARGET.
std::string temporary_name(const std::string& target, unsigned long n);

// Whether process `pid` still runs (or exists under another owner).
bool process_runs(pid_t pid);

// Removes what dead runs left beside TARGET: entries of its folder named TARGET.tmp.<pid>.<x>,
// owned by this user, whose <pid> runs no more, where <x> is digits (a regular file or a link,
// removed) or six letters and digits (a folder: the files in it, then the folder, kept if
// anything else is inside) or `staged-` and six letters and digits (a staged output's folder,
// removed with everything in it). Nothing else is touched. Each folder is listed once per
// process.
void remove_dead_runs_temporaries(const std::string& target);

// Whether `name` (a file name) is one of the temporaries above of a run that runs no more; its
// TARGET's name into `target`.
bool names_dead_runs_temporary(const std::string& name, std::string& target);

}  // namespace fdh::verify
