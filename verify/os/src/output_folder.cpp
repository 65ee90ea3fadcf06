#include "fdh/os/output_folder.hpp"

#include <fcntl.h>
#include <fnmatch.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <typeinfo>

#include "fdh/os/atomic_file.hpp"
#include "fdh/os/folders.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& dir, const std::string& what, int errno_value) {
  throw std::runtime_error(dir + ": " + what + ": " + system_reason(errno_value));
}

// `dir` without trailing slashes; "." and ".." made absolute (their names cannot be renamed);
// a link to a folder resolved, so that the folder it names is replaced and the link stays.
fs::path target_of(std::string dir) {
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  fs::path p(dir);
  std::error_code ec;
  if (p.filename() == "." || p.filename() == ".." || fs::is_symlink(p, ec)) {
    const fs::path c = fs::weakly_canonical(p, ec);
    if (!ec) p = c;
  }
  return p;
}

fs::path parent_of(const fs::path& p) {
  return p.parent_path().empty() ? fs::path(".") : p.parent_path();
}

// Refuses a folder that is the current folder or holds it: it is replaced whole.
void refuse_current_folder(const std::string& dir, const fs::path& target) {
  std::error_code ec;
  const fs::path t = fs::canonical(target, ec);
  if (ec) return;  // absent: made by the run
  const fs::path cwd = fs::current_path(ec);
  if (ec) return;
  const std::string ts = t.string(), cs = cwd.string();
  if (cs == ts || (cs.rfind(ts, 0) == 0 && (ts == "/" || cs[ts.size()] == '/')))
    throw std::runtime_error(dir +
                             ": is the current folder or holds it; an output folder is replaced "
                             "whole when the run ends, so name a folder inside it");
}

bool owned(const std::vector<std::string>& patterns, const std::string& rel) {
  for (const std::string& p : patterns)
    if (::fnmatch(p.c_str(), rel.c_str(), FNM_PATHNAME) == 0) return true;
  return false;
}

const char* kind_of(const struct stat& st) {
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "a device";
}

// One entry of the old folder carried into the new one (see the header): `from` and `to` its
// paths, `rel` its name relative to the output folder.
void carry(const fs::path& from, const fs::path& to, const std::string& rel,
           const std::vector<std::string>& patterns, const std::string& dir);

// A dead run's temporary of one of the job's own files (named after it, ours, its process gone):
// left behind, as a run that writes the file removes it (fdh/os/temporaries.hpp).
bool owned_litter(const fs::path& p, const std::string& rel,
                  const std::vector<std::string>& patterns) {
  std::string target;
  struct stat st {};
  return names_dead_runs_temporary(p.filename().string(), target) &&
         owned(patterns, rel.empty() ? target : rel + "/" + target) &&
         ::lstat(p.c_str(), &st) == 0 && st.st_uid == ::geteuid();
}

// What the old folder `from` holds and the job does not own, into `to`; an entry the run wrote
// wins, and a dead run's temporary of an owned file is left behind.
void carry_folder(const fs::path& from, const fs::path& to, const std::string& rel,
                  const std::vector<std::string>& patterns, const std::string& dir) {
  std::error_code ec;
  for (fs::directory_iterator it(from, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const std::string r = rel.empty() ? name : rel + "/" + name;
    if (owned(patterns, r) || owned_litter(it->path(), rel, patterns)) continue;
    carry(it->path(), to / name, r, patterns, dir);
  }
  if (ec)
    throw std::runtime_error(dir + ": cannot read the folder " + from.string() + ": " +
                             ec.message());
}

void carry(const fs::path& from, const fs::path& to, const std::string& rel,
           const std::vector<std::string>& patterns, const std::string& dir) {
  struct stat st {
  }, there{};
  if (::lstat(from.c_str(), &st) != 0) return;  // gone meanwhile
  const bool written = ::lstat(to.c_str(), &there) == 0;
  std::error_code ec;
  if (S_ISDIR(st.st_mode)) {
    if (written && !S_ISDIR(there.st_mode)) return;
    if (!written && ::mkdir(to.c_str(), 0700) != 0)
      fail(dir, "cannot carry the folder " + rel + " into the new output", errno);
    carry_folder(from, to, rel, patterns, dir);
    if (!written) ::chmod(to.c_str(), st.st_mode & 07777);
  } else if (written) {
    return;
  } else if (S_ISREG(st.st_mode)) {
    if (::link(from.c_str(), to.c_str()) != 0 &&
        !fs::copy_file(from, to, fs::copy_options::none, ec))
      throw std::runtime_error(dir + ": cannot carry " + rel +
                               " into the new output: " + ec.message());
  } else if (S_ISLNK(st.st_mode)) {
    fs::copy_symlink(from, to, ec);
    if (ec) throw std::runtime_error(dir + ": cannot carry the link " + rel + ": " + ec.message());
  } else {
    throw std::runtime_error(dir + "/" + rel + ": is " + kind_of(st) +
                             ", which the new output cannot carry; move it out of the folder");
  }
}

mode_t default_folder_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0777 & ~mask;
}

// The swap where the file system has no RENAME_EXCHANGE (EINVAL): the old folder renamed onto
// an empty private folder, then the new one into place (back again if that fails). DIR is
// absent between the two renames.
bool swap_by_two_renames(const std::string& staged, const std::string& dir) {
  std::string old = dir + ".tmp." + std::to_string(::getpid()) + ".staged-XXXXXX";
  if (!::mkdtemp(old.data())) return false;
  const RecordedTemporary recorded = RecordedTemporary::tree(old);
  if (std::rename(dir.c_str(), old.c_str()) != 0) {
    const int err = errno;
    ::rmdir(old.c_str());
    errno = err;
    return false;
  }
  if (std::rename(staged.c_str(), dir.c_str()) != 0) {
    const int err = errno;
    std::rename(old.c_str(), dir.c_str());
    errno = err;
    return false;
  }
  remove_tree(old.c_str());
  return true;
}

// Puts `staged` at `dir`: exchanged with the old folder if `had`, else where nothing is.
bool swap_in(const std::string& staged, const std::string& dir, bool had) {
  if (::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, dir.c_str(),
                  had ? RENAME_EXCHANGE : RENAME_NOREPLACE) == 0)
    return true;
  if (errno != EINVAL) return false;
  return had ? swap_by_two_renames(staged, dir) : std::rename(staged.c_str(), dir.c_str()) == 0;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size())
    s.replace(at, from.size(), to);
  return s;
}

}  // namespace

void check_output_folder(const std::string& dir, const std::vector<std::string>& files) {
  check_output_dir(dir, files);
  const fs::path target = target_of(dir);
  refuse_current_folder(dir, target);
  const fs::path parent = parent_of(target);
  struct stat st {};
  if (::stat(parent.c_str(), &st) == 0 && ::access(parent.c_str(), W_OK | X_OK) != 0)
    fail(dir,
         "cannot write into its parent folder " + parent.string() +
             " (the new output is made there, then swapped in)",
         errno);
}

OutputFolder::OutputFolder(const std::string& dir, std::vector<std::string> owned)
    : owned_(std::move(owned)) {
  if (dir.empty()) throw std::runtime_error("an output folder is empty");
  const fs::path target = target_of(dir);
  refuse_current_folder(dir, target);
  dir_ = target.string();
  std::error_code ec;
  fs::create_directories(parent_of(target), ec);
  if (ec) throw std::runtime_error(dir + ": cannot create its parent folder: " + ec.message());
  remove_dead_runs_temporaries(dir_);
  std::string pattern = dir_ + ".tmp." + std::to_string(::getpid()) + ".staged-XXXXXX";
  if (!::mkdtemp(pattern.data())) fail(dir, "cannot make the new output's folder", errno);
  staged_ = pattern;
  recorded_ = RecordedTemporary::tree(staged_);
}

OutputFolder::~OutputFolder() {
  if (!committed_) remove_tree(staged_.c_str());
}

void OutputFolder::commit() {
  struct stat old {};
  const bool had = ::lstat(dir_.c_str(), &old) == 0;
  if (had && !S_ISDIR(old.st_mode))
    throw std::runtime_error(dir_ + ": is not a folder (an output folder was asked for)");
  if (had) carry_folder(dir_, staged_, "", owned_, dir_);
  ::chmod(staged_.c_str(), had ? old.st_mode & 07777 : default_folder_mode());
  sync_folder(staged_);
  if (!swap_in(staged_, dir_, had)) {
    if (errno == EEXIST && !had) return commit();  // a folder appeared meanwhile: swap with it
    fail(dir_, "cannot swap in the new output", errno);
  }
  committed_ = true;
  remove_tree(staged_.c_str());  // the old output, now at the private folder's name (if any)
  sync_folder(parent_of(fs::path(dir_)).string());
}

void OutputFolder::publish(const std::function<void(const std::string& into)>& write) {
  try {
    write(staged_);
    commit();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (typeid(e) != typeid(std::runtime_error) || what.find(staged_) == std::string::npos) throw;
    throw std::runtime_error(replace_all(what, staged_, dir_));
  }
}

}  // namespace fdh::verify
