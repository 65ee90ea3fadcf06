#include "fdh/os/work_folder.hpp"

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "fdh/os/atomic_file.hpp"
#include "fdh/os/folders.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// The lock file's path, once WORK exists (the lock is taken in the member initialiser).
std::string made(const std::string& dir) {
  make_folder(dir);
  return (fs::path(dir) / "lock").string();
}

}  // namespace

WorkFolder::WorkFolder(const std::string& dir, double lock_wait_seconds)
    : dir_(dir),
      lock_path_(made(dir)),
      tmp_((fs::path(dir) / "tmp").string()),
      lock_(lock_path_, lock_wait_seconds) {
  make_folder(tmp_);
  // Emptied by clear_stale_temporaries: it must be the folder itself, never a link to someone
  // else's.
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(tmp_, ec)))
    throw std::runtime_error(tmp_ + ": is not a folder (the run's temporaries go there)");
}

void WorkFolder::clear_stale_temporaries() const {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(tmp_, ec), end; !ec && it != end; it.increment(ec))
    stale.push_back(it->path());
  for (const fs::path& p : stale)
    if (!ec) fs::remove_all(p, ec);
  if (ec) throw std::runtime_error(tmp_ + ": cannot clean up: " + ec.message());
}

void WorkFolder::write_whole(const std::string& target, const std::string& text) const {
  write_file_atomically(target, text, tmp_);
}

}  // namespace fdh::verify
