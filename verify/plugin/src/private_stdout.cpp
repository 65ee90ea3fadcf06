#include "private_stdout.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ext/stdio_filebuf.h>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace fdh::verify::plugin {
namespace {

int g_saved = -1;  // the real standard output while diverted
std::unique_ptr<__gnu_cxx::stdio_filebuf<char>> g_buffer;
std::streambuf* g_previous = nullptr;

}  // namespace

void divert_stdout() {
  if (g_saved >= 0) return;
  std::cout.flush();
  std::fflush(stdout);
  const int saved = ::fcntl(1, F_DUPFD_CLOEXEC, 3);
  if (saved < 0 || ::dup2(2, 1) < 0) {
    const std::string why = std::strerror(errno);
    if (saved >= 0) ::close(saved);
    throw std::runtime_error("cannot keep plug-ins off standard output: " + why);
  }
  // The buffer owns a copy of its own: `saved` goes back onto fd 1 in restore_stdout.
  const int copy = ::fcntl(saved, F_DUPFD_CLOEXEC, 3);
  if (copy < 0) {
    const std::string why = std::strerror(errno);
    ::dup2(saved, 1), ::close(saved);
    throw std::runtime_error("cannot keep plug-ins off standard output: " + why);
  }
  g_saved = saved;
  g_buffer = std::make_unique<__gnu_cxx::stdio_filebuf<char>>(copy, std::ios::out);
  g_previous = std::cout.rdbuf(g_buffer.get());
}

void restore_stdout() {
  if (g_saved < 0) return;
  std::cout.flush();  // fdhcert's own output, on the real standard output
  const bool failed = !std::cout;
  std::fflush(stdout);  // what plug-ins left in stdio's buffer goes to standard error
  std::cout.rdbuf(g_previous);
  g_buffer.reset();
  ::dup2(g_saved, 1);
  ::close(g_saved);
  g_saved = -1;
  if (failed) std::cout.setstate(std::ios::badbit);  // main reports the failed write
}

}  // namespace fdh::verify::plugin
