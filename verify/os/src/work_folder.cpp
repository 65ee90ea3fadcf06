#include "fdh/os/work_folder.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "fdh/os/atomic_file.hpp"
#include "fdh/os/folders.hpp"
#include "fdh/os/temporaries.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse_followed(const std::string& path, int err, const std::string& what) {
  if (err == ELOOP)
    throw std::runtime_error(path + ": is a symbolic link, not " + what +
                             "; fdhcert never follows a link in its work folder (remove it)");
  if (err == ENOTDIR) throw std::runtime_error(path + ": is not a folder (" + what + ")");
  throw std::runtime_error(path + ": cannot open " + what + ": " + system_reason(err));
}

// NAME in the folder open as `at`, made if absent, opened as a folder through no link.
int open_folder(int at, const std::string& name, const std::string& path, const std::string& what) {
  if (::mkdirat(at, name.c_str(), 0777) != 0 && errno != EEXIST)
    throw std::runtime_error(path + ": cannot create the folder: " + system_reason(errno));
  const int fd = ::openat(at, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd >= 0) return fd;
  int err = errno;
  struct stat st {};  // O_DIRECTORY | O_NOFOLLOW gives ENOTDIR for a link: tell them apart
  if (err == ENOTDIR && ::fstatat(at, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 &&
      S_ISLNK(st.st_mode))
    err = ELOOP;
  refuse_followed(path, err, what);
}

// Removes everything in the folder open as `fd`: links and files unlinked (never followed),
// folders emptied the same way first. False with errno set on failure.
bool empty_folder(int fd) {
  const int listing = ::dup(fd);
  DIR* d = listing < 0 ? nullptr : ::fdopendir(listing);
  if (!d) return false;
  std::vector<std::string> names;
  while (const dirent* e = ::readdir(d))
    if (std::string(e->d_name) != "." && std::string(e->d_name) != "..") names.push_back(e->d_name);
  ::closedir(d);
  for (const std::string& n : names) {
    if (::unlinkat(fd, n.c_str(), 0) == 0) continue;
    if (errno != EISDIR && errno != EPERM) return false;
    const int sub = ::openat(fd, n.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (sub < 0) return false;
    const bool ok = empty_folder(sub);
    ::close(sub);
    if (!ok || ::unlinkat(fd, n.c_str(), AT_REMOVEDIR) != 0) return false;
  }
  return true;
}

std::string made_parent(const std::string& dir) {
  const fs::path parent = fs::path(dir).parent_path();
  if (!parent.empty()) make_folder(parent.string());
  return dir;
}

}  // namespace

void refuse_link(const std::string& path, const std::string& what) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) refuse_followed(path, ELOOP, what);
}

WorkFolder::WorkFolder(const std::string& dir, double lock_wait_seconds)
    : dir_(made_parent(dir)),
      lock_path_((fs::path(dir) / "lock").string()),
      tmp_((fs::path(dir) / "tmp").string()) {
  dir_fd_ = open_folder(AT_FDCWD, dir_, dir_, "fdhcert's work folder");
  try {
    lock_ = std::make_unique<FileLock>(dir_fd_, "lock", lock_path_, lock_wait_seconds);
    tmp_fd_ = open_folder(dir_fd_, "tmp", tmp_, "the folder of the run's temporaries");
  } catch (...) {
    ::close(dir_fd_);
    throw;
  }
}

WorkFolder::~WorkFolder() {
  if (tmp_fd_ >= 0) ::close(tmp_fd_);
  ::close(dir_fd_);
}

void WorkFolder::clear_stale_temporaries() const {
  if (!empty_folder(tmp_fd_))
    throw std::runtime_error(tmp_ + ": cannot clean up: " + system_reason(errno));
}

void WorkFolder::make_subfolder(const std::string& name) const {
  ::close(open_folder(dir_fd_, name, dir_ + "/" + name, "a run's folder"));
}

void WorkFolder::write_whole(const std::string& target, const std::string& text) const {
  static std::atomic<unsigned long> serial{0};
  const std::string name = std::to_string(::getpid()) + "." + std::to_string(serial++);
  const RecordedTemporary recorded(tmp_ + "/" + name);
  const int fd =
      ::openat(tmp_fd_, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error(target + ": cannot write file: " + system_reason(errno));
  int err = write_all(fd, text) ? 0 : errno;
  if (!err && ::fsync(fd) != 0 && errno != EINVAL) err = errno;
  if (::close(fd) != 0 && !err && errno != EINTR) err = errno;
  // Inside WORK: from its descriptor, component by component, through no link.
  const std::string inside = dir_ + "/";
  int parent = AT_FDCWD, opened = -1;
  std::string leaf = target;
  try {
    if (!err && target.compare(0, inside.size(), inside) == 0) {
      const fs::path rel = target.substr(inside.size());
      leaf = rel.filename().string();
      parent = dir_fd_;
      for (const fs::path& part : rel.parent_path()) {
        const int next = open_folder(parent, part.string(), target, "a run's folder");
        if (opened >= 0) ::close(opened);
        parent = opened = next;
      }
      struct stat st {};
      if (::fstatat(parent, leaf.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(st.st_mode))
        refuse_followed(target, ELOOP, "a run's file");
      if (::fstatat(parent, leaf.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && !S_ISREG(st.st_mode))
        throw std::runtime_error(target + ": is not a regular file; refusing to replace it");
    } else if (!err) {
      check_output_path(target);
    }
    if (!err && ::renameat(tmp_fd_, name.c_str(), parent, leaf.c_str()) != 0) err = errno;
  } catch (...) {
    if (opened >= 0) ::close(opened);
    ::unlinkat(tmp_fd_, name.c_str(), 0);
    throw;
  }
  if (opened >= 0) ::close(opened);
  if (err) {
    ::unlinkat(tmp_fd_, name.c_str(), 0);
    throw std::runtime_error(target + ": cannot write file: " + system_reason(err));
  }
}

}  // namespace fdh::verify
