// A child process that dies with its parent: fork, PR_SET_PDEATHSIG and wait, written once for
// the chart drawing (gnuplot), the plug-in probe and fuzz's workers.
#pragma once

#include <sys/types.h>

#include <optional>
#include <string>

namespace fdh::verify {

// How a child ended (waitpid's status).
struct ChildStatus {
  int raw = 0;
  bool exited() const;
  int exit_code() const;  // when exited()
  bool ok() const { return exited() && exit_code() == 0; }
  // "exit status 3" or "signal 9".
  std::string words() const;
};

class ChildProcess {
 public:
  // Forks (after flushing stdio, so that nothing buffered is written twice). The child is
  // killed (SIGKILL) when this process dies, runs body() and exits with what it returns (3 if it
  // throws). In a process with threads the child may call async-signal-safe functions only;
  // body is a plain function pointer and an argument so that calling it allocates nothing.
  // Throws std::runtime_error when no process can be made.
  template <class Body>
  explicit ChildProcess(const Body& body)
      : ChildProcess([](const void* b) { return (*static_cast<const Body*>(b))(); }, &body) {}
  ChildProcess(int (*run)(const void*), const void* arg);
  // A child never waited for is killed and reaped.
  ~ChildProcess();
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ChildProcess& operator=(ChildProcess&& other) noexcept;  // ends this one first, as above

  pid_t pid() const { return pid_; }
  void kill();                        // SIGKILL; wait() still reaps it
  ChildStatus wait();                 // blocks until it ends
  std::optional<ChildStatus> poll();  // its status if it has ended, without blocking

 private:
  pid_t pid_ = -1;
};

}  // namespace fdh::verify
