#include "fdh/os/temporaries.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <vector>

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// The record: fixed slots, so that a signal handler can walk it (no allocation, no lock). A
// slot is 0 free, 1 being filled, 2 a file, 3 a folder, 4 a folder removed whole (a tree).
constexpr int kSlots = 256;
constexpr std::size_t kPathMax = 4096;
struct Slot {
  std::atomic<int> state{0};
  char path[kPathMax];
};
Slot g_slots[kSlots];

int record(const std::string& path, int kind) {
  if (path.size() >= kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!g_slots[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].state.store(kind, std::memory_order_release);
    return i;
  }
  return -1;
}

void forget(int slot) {
  if (slot >= 0) g_slots[slot].state.store(0, std::memory_order_release);
}

void on_signal(int sig) {
  const int saved = errno;
  remove_recorded_temporaries();
  ::signal(sig, SIG_DFL);  // then the default action: the process ends by this signal
  ::raise(sig);
  errno = saved;
}

constexpr int kTreeDepth = 64;

bool dot_or_dot_dot(const char* n) {
  return n[0] == '.' && (n[1] == 0 || (n[1] == '.' && n[2] == 0));
}

// Removes everything in the open folder `fd`: files and links by unlinkat, folders by
// remove_tree_at. Passes over the listing until one removes nothing (removing while listing may
// skip entries). getdents64 into a buffer on the stack: async-signal-safe.
void empty_folder(int fd, int depth) noexcept;

// Removes folder `name` of `parent_fd` and all it holds; true if it is gone.
bool remove_tree_at(int parent_fd, const char* name, int depth) noexcept {
  const int fd = ::openat(parent_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return false;
  if (depth < kTreeDepth) empty_folder(fd, depth);
  ::close(fd);
  return ::unlinkat(parent_fd, name, AT_REMOVEDIR) == 0;
}

void empty_folder(int fd, int depth) noexcept {
  alignas(8) char buf[2048];
  for (bool removed = true; removed;) {
    removed = false;
    if (::lseek(fd, 0, SEEK_SET) != 0) return;
    for (long n; (n = ::syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0;)
      for (long at = 0; at < n;) {
        // glibc's dirent64 has the kernel's layout (linux_dirent64, getdents64(2)).
        const auto* e = reinterpret_cast<const struct dirent64*>(buf + at);
        at += e->d_reclen;
        if (dot_or_dot_dot(e->d_name)) continue;
        if (e->d_type != DT_DIR && ::unlinkat(fd, e->d_name, 0) == 0)
          removed = true;
        else if ((e->d_type == DT_DIR || errno == EISDIR) &&
                 remove_tree_at(fd, e->d_name, depth + 1))
          removed = true;
      }
  }
}

// A dead run's temporary, found in a folder's listing.
struct Stale {
  std::string name;
  pid_t pid;
  bool folder;        // named as mkdtemp names a folder
  bool tree = false;  // a staged output's folder (staged-XXXXXX)
};

bool all_of(const std::string& s, int (*pred)(int)) {
  for (const char c : s)
    if (!pred(static_cast<unsigned char>(c))) return false;
  return !s.empty();
}

// TARGET, the pid and the kind of a name TARGET.tmp.<pid>.<x>; false for any other name.
bool parse_temporary(const std::string& name, std::string& target, Stale& s) {
  const std::size_t dot = name.rfind('.');
  if (dot == std::string::npos) return false;
  const std::string x = name.substr(dot + 1), rest = name.substr(0, dot);
  const std::size_t tmp = rest.rfind(".tmp.");
  if (tmp == std::string::npos || tmp == 0) return false;
  const std::string pid = rest.substr(tmp + 5);
  if (!all_of(pid, ::isdigit) || pid.size() > 9) return false;
  const bool staged =
      x.size() == 13 && x.rfind("staged-", 0) == 0 && all_of(x.substr(7), ::isalnum);
  if (all_of(x, ::isdigit))
    s.folder = false;
  else if ((x.size() == 6 && all_of(x, ::isalnum)) || staged)
    s.folder = true;
  else
    return false;
  s.tree = staged;
  target = rest.substr(0, tmp);
  s.name = name;
  s.pid = pid_t(std::stol(pid));
  return s.pid > 0;
}

// A dead run's folder: the files and links in it, then the folder if that emptied it.
void remove_stale_folder(int dir_fd, const std::string& name) {
  const int fd = ::openat(dir_fd, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  if (DIR* d = ::fdopendir(fd)) {
    std::vector<std::string> files;
    while (const dirent* e = ::readdir(d)) {
      struct stat st {};
      if (::fstatat(fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 &&
          (S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)))
        files.push_back(e->d_name);
    }
    for (const std::string& f : files) ::unlinkat(fd, f.c_str(), 0);
    ::closedir(d);  // closes fd
  } else {
    ::close(fd);
  }
  ::unlinkat(dir_fd, name.c_str(), AT_REMOVEDIR);  // fails, harmlessly, if anything is left
}

// The folders listed so far and the dead runs' temporaries in each, by target name.
std::mutex g_listed_mutex;
std::map<std::string, std::multimap<std::string, Stale>> g_listed;

std::multimap<std::string, Stale> list_stale(const std::string& dir) {
  std::multimap<std::string, Stale> found;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::string target;
    Stale s;
    if (parse_temporary(it->path().filename().string(), target, s))
      found.emplace(target, std::move(s));
  }
  return found;
}

}  // namespace

RecordedTemporary::RecordedTemporary(const std::string& path, bool folder)
    : slot_(record(path, folder ? 3 : 2)) {}

RecordedTemporary RecordedTemporary::tree(const std::string& path) {
  RecordedTemporary t;
  t.slot_ = record(path, 4);
  return t;
}

RecordedTemporary::~RecordedTemporary() {
  forget(slot_);
}

RecordedTemporary::RecordedTemporary(RecordedTemporary&& other) noexcept : slot_(other.slot_) {
  other.slot_ = -1;
}

RecordedTemporary& RecordedTemporary::operator=(RecordedTemporary&& other) noexcept {
  if (this != &other) {
    forget(slot_);
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

void remove_tree(const char* path) noexcept {
  struct stat st {};
  if (::lstat(path, &st) != 0 || !S_ISDIR(st.st_mode)) return;
  remove_tree_at(AT_FDCWD, path, 0);
}

void remove_recorded_temporaries() noexcept {
  for (const int kind : {2, 3, 4})
    for (Slot& s : g_slots) {
      if (s.state.load(std::memory_order_acquire) != kind) continue;
      if (kind == 2)
        ::unlink(s.path);
      else if (kind == 3)
        ::rmdir(s.path);
      else
        remove_tree(s.path);
    }
}

void forget_recorded_temporaries() noexcept {
  for (Slot& s : g_slots) s.state.store(0, std::memory_order_relaxed);
}

void remove_temporaries_on_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGTERM);
  sigaddset(&sa.sa_mask, SIGINT);
  for (const int sig : {SIGTERM, SIGINT}) {
    struct sigaction old {};
    // A signal ignored when fdhcert started (nohup, a background job's SIGINT) stays ignored.
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &sa, nullptr);
  }
}

std::string temporary_name(const std::string& target, unsigned long n) {
  return target + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(n);
}

bool process_runs(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno != ESRCH;
}

void remove_dead_runs_temporaries(const std::string& target) {
  const fs::path p(target);
  const std::string dir = p.parent_path().empty() ? "." : p.parent_path().string();
  const std::string name = p.filename().string();
  std::vector<Stale> mine;
  {
    const std::lock_guard<std::mutex> lock(g_listed_mutex);
    auto listed = g_listed.find(dir);
    if (listed == g_listed.end()) listed = g_listed.emplace(dir, list_stale(dir)).first;
    const auto [from, to] = listed->second.equal_range(name);
    for (auto it = from; it != to; ++it) mine.push_back(it->second);
    listed->second.erase(from, to);
  }
  if (mine.empty()) return;
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd < 0) return;
  for (const Stale& s : mine) {
    struct stat st {};
    if (s.pid == ::getpid() || process_runs(s.pid) ||
        ::fstatat(dir_fd, s.name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0 ||
        st.st_uid != ::geteuid())
      continue;
    if (!s.folder && (S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)))
      ::unlinkat(dir_fd, s.name.c_str(), 0);
    else if (s.tree && S_ISDIR(st.st_mode))
      remove_tree_at(dir_fd, s.name.c_str(), 0);
    else if (s.folder && S_ISDIR(st.st_mode))
      remove_stale_folder(dir_fd, s.name);
  }
  ::close(dir_fd);
}

bool names_dead_runs_temporary(const std::string& name, std::string& target) {
  Stale s;
  return parse_temporary(name, target, s) && s.pid != ::getpid() && !process_runs(s.pid);
}

}  // namespace fdh::verify
