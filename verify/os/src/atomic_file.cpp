#include "fdh/os/atomic_file.hpp"

#include "fdh/os/temporaries.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <streambuf>

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// Beside `path` (after removing what dead runs left there), or in `temp_dir` when one is given.
std::string temp_path(const std::string& path, const std::string& temp_dir = "") {
  static std::atomic<unsigned long> serial{0};  // unique per call: threads may write at once
  const unsigned long n = serial++;
  if (!temp_dir.empty())
    return temp_dir + "/" + std::to_string(::getpid()) + "." + std::to_string(n);
  remove_dead_runs_temporaries(path);
  return temporary_name(path, n);
}

[[noreturn]] void fail(const std::string& path, const std::string& what, int errno_value) {
  throw std::runtime_error(path + ": " + what + ": " + system_reason(errno_value));
}

// What kind of thing stands at `path` (following links), in words; "" for a regular file or
// nothing at all.
std::string not_regular(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "";
  if (S_ISREG(st.st_mode)) return "";
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

void refuse_non_regular(const std::string& path) {
  const std::string kind = not_regular(path);
  if (!kind.empty())
    throw std::runtime_error(path + ": is " + kind +
                             ", not a regular file; refusing to replace it with an output");
}

// `dir` is a folder we may create files in.
void check_writable_folder(const std::string& dir, const std::string& for_path) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) fail(for_path, "cannot write into folder " + dir, errno);
  if (!S_ISDIR(st.st_mode)) throw std::runtime_error(for_path + ": " + dir + " is not a folder");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    fail(for_path, "cannot write into folder " + dir, errno);
}

std::string folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

// The nearest existing ancestor of an absent folder must be a writable folder.
void check_creatable(const std::string& dir, const std::string& for_path) {
  fs::path p(dir);
  std::error_code ec;
  while (!p.empty() && !fs::exists(fs::symlink_status(p, ec)) && p.has_parent_path() &&
         p.parent_path() != p)
    p = p.parent_path();
  if (p.empty() || !fs::exists(fs::symlink_status(p, ec))) p = ".";
  check_writable_folder(p.string(), for_path);
}

// A new temporary file for `path`, named in `tmp` and recorded in `recorded`. A name taken
// already (planted there, even as a link: O_EXCL never opens through one) is passed over.
int open_temp(const std::string& path, const std::string& temp_dir, std::string& tmp,
              RecordedTemporary& recorded) {
  refuse_non_regular(path);
  for (int attempt = 0;; ++attempt) {
    tmp = temp_path(path, temp_dir);
    recorded = RecordedTemporary(tmp);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    const int err = errno;
    recorded = RecordedTemporary();
    if (err != EEXIST || attempt == 1000) fail(path, "cannot write file", err);
  }
}

// fsync, close and rename into place (refusing a path that became a non-regular file); on any
// failure the temporary file is removed and the error names the path and the reason.
void publish(int fd, const std::string& tmp, const std::string& path, int earlier_errno) {
  int err = earlier_errno;
  if (!err && ::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) err = errno;
  if (::close(fd) != 0 && !err && errno != EINTR) err = errno;
  if (!err) {
    try {
      refuse_non_regular(path);
    } catch (...) {
      ::unlink(tmp.c_str());
      throw;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  }
  if (err) {
    ::unlink(tmp.c_str());
    fail(path, "cannot write file", err);
  }
}

}  // namespace

bool write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t w = ::write(fd, data.data(), data.size());
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      if (w == 0) errno = EIO;
      return false;
    }
    data.remove_prefix(std::size_t(w));
  }
  return true;
}

std::string system_reason(int errno_value) {
  return std::strerror(errno_value);
}

void write_file_atomically(const std::string& path, const std::string& content) {
  write_file_atomically(path, content, "");
}

void write_file_atomically(const std::string& path, const std::string& content,
                           const std::string& temp_dir) {
  std::string tmp;
  RecordedTemporary recorded;  // removed by SIGTERM or SIGINT until published
  const int fd = open_temp(path, temp_dir, tmp, recorded);
  const int err = write_all(fd, content) ? 0 : errno;
  publish(fd, tmp, path, err);
}

bool file_holds(const std::string& path, const std::string& text) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) ||
      st.st_size != static_cast<off_t>(text.size()))
    return false;
  std::ifstream in(path, std::ios::binary);
  std::string got(text.size(), '\0');
  return in.read(got.data(), std::streamsize(got.size())) && got == text;
}

void check_output_path(const std::string& path, bool folder_made_by_run) {
  if (path.empty()) throw std::runtime_error("an output path is empty");
  refuse_non_regular(path);
  const std::string dir = folder_of(path);
  std::error_code ec;
  if (folder_made_by_run && !fs::exists(dir, ec))
    check_creatable(dir, path);
  else
    check_writable_folder(dir, path);
}

void check_output_dir(const std::string& dir, const std::vector<std::string>& files) {
  if (dir.empty()) throw std::runtime_error("an output folder is empty");
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode))
      throw std::runtime_error(dir + ": is not a folder (an output folder was asked for)");
    check_writable_folder(dir, dir);
  } else {
    check_creatable(dir, dir);
  }
  for (const std::string& f : files) check_output_path((fs::path(dir) / f).string(), true);
}

// A streambuf over a file descriptor that remembers the first failed write's errno.
class AtomicFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), buf_(1 << 16) { setp(buf_.data(), buf_.data() + buf_.size()); }
  int fd() const { return fd_; }
  int error() const { return error_; }
  int sync() override { return drain() ? 0 : -1; }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }

 private:
  bool drain() {
    if (error_) return false;
    const std::size_t n = std::size_t(pptr() - pbase());
    if (n && !write_all(fd_, std::string_view(pbase(), n))) error_ = errno;
    setp(buf_.data(), buf_.data() + buf_.size());
    return error_ == 0;
  }
  int fd_;
  int error_ = 0;
  std::vector<char> buf_;
};

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  buf_ = std::make_unique<Buffer>(open_temp(path_, "", tmp_, recorded_));
  out_ = std::make_unique<std::ostream>(buf_.get());
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  ::close(buf_->fd());
  ::unlink(tmp_.c_str());
}

std::ostream& AtomicFile::stream() {
  return *out_;
}

void AtomicFile::commit() {
  out_->flush();
  committed_ = true;  // publish closes and renames or removes the temporary file
  publish(buf_->fd(), tmp_, path_, buf_->error() ? buf_->error() : (*out_ ? 0 : EIO));
}

}  // namespace fdh::verify
