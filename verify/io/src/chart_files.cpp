#include "chart_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "fdh/os/atomic_file.hpp"

namespace fdh::verify {
namespace {

std::uint32_t big_endian(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
  return v;
}

}  // namespace

// The PNG specification's file layout (ISO/IEC 15948, section 5): signature, then chunks of
// length (4 bytes), type (4), data, CRC-32 of type and data (4); IEND is the last.
std::string png_problem(std::string_view b) {
  static const std::string_view signature("\x89PNG\r\n\x1a\n", 8);
  if (b.substr(0, 8) != signature)
    return "no PNG signature (" + std::to_string(b.size()) + " bytes)";
  for (std::size_t at = 8; at < b.size();) {
    if (b.size() - at < 12) return "a chunk cut at byte " + std::to_string(at);
    const std::uint32_t length = big_endian(b, at);
    if (length > b.size() - at - 12) return "a chunk cut at byte " + std::to_string(at);
    const std::string_view typed = b.substr(at + 4, 4 + std::size_t(length));
    const auto crc =
        std::uint32_t(::crc32(0, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size())));
    if (crc != big_endian(b, at + 8 + length)) return "a bad CRC at byte " + std::to_string(at);
    at += 12 + length;
    if (typed.substr(0, 4) == "IEND")
      return at == b.size() ? "" : "bytes after IEND at byte " + std::to_string(at);
  }
  return "no IEND chunk (cut at " + std::to_string(b.size()) + " bytes)";
}

std::string svg_problem(std::string_view b) {
  while (!b.empty() && std::isspace(static_cast<unsigned char>(b.back()))) b.remove_suffix(1);
  static const std::string_view end = "</svg>";
  if (b.size() >= end.size() && b.substr(b.size() - end.size()) == end) return "";
  return "no closing </svg> (cut at " + std::to_string(b.size()) + " bytes)";
}

PrivateFolder::PrivateFolder(const std::string& dir, const std::string& name) {
  std::string pattern = dir + "/" + name + ".tmp." + std::to_string(::getpid()) + ".XXXXXX";
  if (!::mkdtemp(pattern.data()))
    throw std::runtime_error(dir + ": cannot make a folder for the chart " + name + ": " +
                             system_reason(errno));
  path_ = pattern;
  name_ = path_.substr(dir.size() + 1);
  recorded_ = RecordedTemporary(path_, true);
  fd_ = ::open(path_.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd_ < 0) {
    const int err = errno;
    ::rmdir(path_.c_str());
    throw std::runtime_error(path_ + ": cannot open: " + system_reason(err));
  }
}

PrivateFolder::~PrivateFolder() {
  for (const std::string& f : files_) ::unlinkat(fd_, f.c_str(), 0);
  ::close(fd_);
  ::rmdir(path_.c_str());
}

void PrivateFolder::expect(const std::string& file) {
  files_.push_back(file);
  recorded_files_.emplace_back(path_ + "/" + file);
}

std::optional<std::string> PrivateFolder::read(const std::string& file) const {
  const int fd = ::openat(fd_, file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  std::optional<std::string> text;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
    text.emplace();
    char buf[1 << 16];
    ssize_t got;
    while ((got = ::read(fd, buf, sizeof buf)) > 0 || (got < 0 && errno == EINTR))
      if (got > 0) text->append(buf, std::size_t(got));
    if (got < 0) text.reset();
  }
  ::close(fd);
  return text;
}

std::string PrivateFolder::write_probe() {
  const std::string probe = "probe";
  expect(probe);
  const int fd =
      ::openat(fd_, probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) return system_reason(errno);
  const std::string block(1 << 16, '\0');
  int err = write_all(fd, block) ? 0 : errno;
  if (!err && ::fsync(fd) != 0 && errno != EINVAL) err = errno;
  ::close(fd);
  ::unlinkat(fd_, probe.c_str(), 0);
  return err ? system_reason(err) : "";
}

void PrivateFolder::publish(const std::string& file, const std::string& target) {
  if (::renameat(fd_, file.c_str(), AT_FDCWD, target.c_str()) != 0)
    throw std::runtime_error(target + ": cannot write file: " + system_reason(errno));
}

}  // namespace fdh::verify
