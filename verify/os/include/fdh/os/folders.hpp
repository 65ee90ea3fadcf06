// Folders for outputs: made when absent, synced after renames into them (their checks before a
// run: fdh/os/atomic_file.hpp).
#pragma once

#include <string>

namespace fdh::verify {

// Makes `dir` (and its parents) a folder; throws std::runtime_error naming it when it exists and
// is not a folder, or cannot be made.
void make_folder(const std::string& dir);

// Flushes a folder's entries (the renames into it) to the disk.
void sync_folder(const std::string& dir);

}  // namespace fdh::verify
