#include "fdh/os/child_process.hpp"

#include "fdh/os/temporaries.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace fdh::verify {

bool ChildStatus::exited() const {
  return WIFEXITED(raw);
}

int ChildStatus::exit_code() const {
  return WEXITSTATUS(raw);
}

std::string ChildStatus::words() const {
  if (WIFSIGNALED(raw)) return "signal " + std::to_string(WTERMSIG(raw));
  return "exit status " + std::to_string(WEXITSTATUS(raw));
}

ChildProcess::ChildProcess(int (*run)(const void*), const void* arg) {
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ < 0)
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  if (pid_ > 0) return;
  // The child. A parent that died before prctl took effect would leave it running: check.
  if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent) ::_exit(3);
  forget_recorded_temporaries();  // the parent's: a signal to the child must not remove them
  int status = 3;
  try {
    status = run(arg);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fdhcert: %s\n", e.what());
  }
  std::fflush(nullptr);
  ::_exit(status);
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept : pid_(other.pid_) {
  other.pid_ = -1;
}

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  if (this != &other) {
    if (pid_ > 0) kill(), wait();
    pid_ = other.pid_;
    other.pid_ = -1;
  }
  return *this;
}

ChildProcess::~ChildProcess() {
  if (pid_ <= 0) return;
  kill();
  wait();
}

void ChildProcess::kill() {
  if (pid_ > 0) ::kill(pid_, SIGKILL);
}

ChildStatus ChildProcess::wait() {
  ChildStatus s;
  while (::waitpid(pid_, &s.raw, 0) < 0) {
    if (errno == EINTR) continue;
    s.raw = W_EXITCODE(127, 0);  // lost (cannot happen to our own child): a failure
    break;
  }
  pid_ = -1;
  return s;
}

std::optional<ChildStatus> ChildProcess::poll() {
  ChildStatus s;
  const pid_t got = ::waitpid(pid_, &s.raw, WNOHANG);
  if (got == 0 || (got < 0 && errno == EINTR)) return std::nullopt;
  if (got < 0) s.raw = W_EXITCODE(127, 0);
  pid_ = -1;
  return s;
}

}  // namespace fdh::verify
